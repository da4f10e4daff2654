// facets is a normal pattern only (povray: "can only be used in a normal").
#version 3.7;
global_settings { assumed_gamma 1 }
sphere { 0, 1 pigment { facets } }

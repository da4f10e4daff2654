// square cannot be used in a pattern function (povray 3.7 refuses it).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare F = function { pattern { square } }

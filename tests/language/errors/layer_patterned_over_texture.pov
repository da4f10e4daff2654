// A patterned texture cannot lie as a layer over the texture an object
// already has (povray 3.7's message).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Red = sphere { 0, 1 texture { pigment { rgb <1, 0, 0> } } }
object { Red texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } }

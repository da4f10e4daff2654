// Conformance: onion, spherical and cylindrical value functions.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { onion color_map { [0 rgb <0.2, 0.2, 0.6>] [1 rgb <0.9, 0.9, 0.7>] } scale 0.8 } }
sphere { <-2.2, 1, 0>, 1 pigment { onion scale 0.3 } }
sphere { <0, 1, 0>, 1 pigment { spherical color_map { [0 rgb <0.1, 0.3, 0>] [1 rgb <1, 1, 0>] } scale 1.4 translate <0.5, 1.5, -1> } }
box { <1.3, 0, -0.5>, <3.2, 2.2, 0.5> pigment { cylindrical color_map { [0 rgb 0.1] [0.3 rgb <1, 0, 0>] [1 rgb 1] } scale 1.2 translate <2.2, 0, -0.5> } }

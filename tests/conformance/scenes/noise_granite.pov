// Conformance: granite with generators 1 and 2, scaled and rotated.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { granite color_map { [0 rgb <0.9, 0.8, 0.7>] [0.6 rgb <0.3, 0.3, 0.3>] [1 rgb 0] } scale 3 } }
sphere { <-1.3, 1, 0>, 1 pigment { granite rotate <20, 30, 0> } }
sphere { <1.3, 1, 0>, 1 pigment { granite noise_generator 1 scale 0.5 color_map { [0 rgb <1, 0.9, 0.9>] [1 rgb <0.2, 0, 0>] } } }

// Conformance: agate (built-in turbulence, agate_turb) and wrinkles as pigments.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { agate color_map { [0 rgb <0.8, 0.5, 0.2>] [1 rgb <0.1, 0.2, 0.5>] } } }
sphere { <-2.4, 1, 0>, 1 pigment { agate agate_turb 0.5 scale 0.5 } }
sphere { <0, 1, 0>, 1 pigment { wrinkles scale 0.4 color_map { [0 rgb 0] [0.5 rgb <1, 0.5, 0>] [1 rgb 1] } } }
sphere { <2.4, 1, 0>, 1 pigment { wrinkles noise_generator 1 turbulence 0.3 scale 0.3 } }

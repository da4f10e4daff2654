// Conformance: classic turbulence on bozo, gradient and onion, with octaves,
// omega, lambda, vector amounts, and transformations before and after it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { gradient x turbulence <0.8, 0.3, 0.5> octaves 3 color_map { [0 rgb <0.2, 0.2, 0.6>] [1 rgb <0.9, 0.9, 0.7>] } } }
sphere { <-2.4, 1, 0>, 1 pigment { bozo turbulence 0.6 omega 0.7 lambda 3 scale 0.3 } }
sphere { <0, 1, 0>, 1 pigment { onion scale 0.5 turbulence 0.4 octaves 2 color_map { [0 rgb <0.1, 0.3, 0>] [1 rgb <1, 1, 0>] } } }
sphere { <2.4, 1, 0>, 1 pigment { bozo noise_generator 1 turbulence <1, 0, 0> octaves 8 scale <0.2, 0.5, 0.3> rotate 30*z } }

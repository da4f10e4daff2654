// Conformance: bozo, spotted, bumps and dents as pigments, noise generators 1 and 2.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { bozo color_map { [0 rgb <0.2, 0.2, 0.6>] [0.5 rgb <0.9, 0.9, 0.7>] [1 rgb <0.6, 0.1, 0.1>] } scale 0.7 } }
sphere { <-2.4, 1, 0>, 1 pigment { spotted scale 0.25 } }
sphere { <0, 1, 0>, 1 pigment { bumps noise_generator 1 color_map { [0 rgb <0.1, 0.3, 0>] [1 rgb <1, 1, 0>] } scale 0.3 } }
sphere { <2.4, 1, 0>, 1 pigment { dents color_map { [0 rgb 1] [0.3 rgb <1, 0, 0>] [1 rgb 0] } scale 0.2 } }

// Conformance: radial and leopard value functions.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { radial frequency 8 color_map { [0 rgb <0.9, 0.9, 0.9>] [0.5 rgb <0.9, 0.9, 0.9>] [0.5 rgb <0.2, 0.2, 0.4>] [1 rgb <0.2, 0.2, 0.4>] } } }
cylinder { <-2, 0, 0>, <-2, 2.5, 0>, 1 pigment { radial color_map { [0 rgb <1, 0, 0>] [0.33 rgb <0, 1, 0>] [0.66 rgb <0, 0, 1>] [1 rgb <1, 0, 0>] } translate <-2, 0, 0> } }
sphere { <1.5, 1.2, 0>, 1.2 pigment { leopard color_map { [0 rgb <0.9, 0.7, 0.2>] [0.3 rgb <0.3, 0.15, 0>] [1 rgb 0] } scale 0.15 } }
sphere { <0, 0.5, -2>, 0.5 pigment { leopard scale 0.1 } }

// Conformance: hexagon, default and given colours, scaled and rotated.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { hexagon color rgb <0.9, 0.2, 0.2> color rgb <0.9, 0.9, 0.9> color rgb <0.1, 0.2, 0.6> scale 0.7 } }
sphere { <-1.6, 1.2, 0.5>, 1.2 pigment { hexagon scale 0.3 } }
sphere { <1.6, 1.2, 0.5>, 1.2 pigment { hexagon rgb 1, rgb 0.5, rgb 0 scale 0.25 rotate x * 90 } }

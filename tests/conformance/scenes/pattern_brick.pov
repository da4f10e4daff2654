// Conformance: brick with default size and colours, then brick_size and
// mortar, on walls facing several directions.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { brick scale 0.1 } }
box { <-3, 0, 1>, <3, 3.5, 1.5> pigment { brick color rgb 0.8 color rgb <0.5, 0.2, 0.1> brick_size <1, 0.4, 0.6> mortar 0.06 } }
box { <-2.5, 0, -1>, <-1, 2, 0.5> pigment { brick rgb <0.2, 0.2, 0.2>, rgb <0.9, 0.7, 0.3> scale 0.05 } rotate y * 35 }
sphere { <1.5, 1, -0.5>, 1 pigment { brick brick_size 0.5 mortar 0.1 } }

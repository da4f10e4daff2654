// Conformance: declared pattern pigments re-used with extra
// transformations, and texture transforms combined with pigment ones.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

#declare Stripes = pigment { gradient x color_map { [0 rgb <0.8, 0.1, 0.1>] [0.5 rgb <0.8, 0.1, 0.1>] [0.5 rgb 0.9] [1 rgb 0.9] } scale 0.3 }
plane { y, 0 pigment { checker pigment { Stripes }, pigment { Stripes rotate y * 90 } } }
sphere { <-2, 1, 0>, 1 pigment { hexagon pigment { Stripes }, pigment { rgb <0, 0.3, 1> }, pigment { checker rgb 0, rgb 1 scale 0.2 } scale 0.5 } }
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> texture { pigment { onion color_map { [0.3 rgb <1, 1, 0>] [0.7 rgb <0, 0.5, 0.5>] } scale 0.5 } translate x * 0.3 } rotate y * 20 translate z * 0.5 }
sphere { <2.2, 1, 0>, 1 texture { pigment { Stripes rotate z * 45 } scale 2 } rotate y * 30 }

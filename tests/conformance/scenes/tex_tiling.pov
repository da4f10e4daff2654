// Conformance: tiling 1 (squares), 2 (hexagons), 6 (herringbone) and
// 3 (triangles) with colour maps, transformed, and as normals.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { tiling 2 color_map { [0 rgb <0.1, 0.2, 0.5>] [0.8 rgb <0.7, 0.8, 0.9>] [1 rgb 0.2] } scale 0.8 } }
sphere { <-2.6, 1, 0>, 1 pigment { tiling 1 color_map { [0 rgb <1, 0.9, 0.3>] [1 rgb <0.6, 0.1, 0>] } scale 0.3 rotate <30, 20, 0> } }
sphere { <0, 1, 0>, 1 pigment { tiling 3 color_map { [0 rgb <0, 0.4, 0>] [0.5 rgb <0.8, 1, 0.6>] [0.5 rgb <0.3, 0, 0.4>] [1 rgb <1, 0.8, 1>] } scale 0.4 rotate x * -70 } }
sphere { <2.6, 1, 0>, 1 pigment { rgb <0.9, 0.7, 0.5> } normal { tiling 2 0.6 scale 0.25 } }
box { <-3.6, 0, 1.6>, <-1.6, 2.4, 2.4> pigment { tiling 3 color_map { [0 rgb 0] [1 rgb 1] } scale 0.5 rotate x * 90 } }
box { <-1, 0, 1.6>, <1, 2.4, 2.4> pigment { tiling 1 triangle_wave frequency 2 color_map { [0 rgb <0.2, 0.5, 0.2>] [1 rgb 1] } scale 0.4 rotate x * 90 } }
box { <1.6, 0, 1.6>, <3.6, 2.4, 2.4> pigment { tiling 6 color_map { [0 rgb <0.6, 0.3, 0.1>] [0.5 rgb <1, 0.8, 0.5>] [0.5 rgb <0.3, 0.2, 0.1>] [1 rgb <0.8, 0.6, 0.4>] } scale 0.25 rotate x * 90 } normal { tiling 3 0.8 scale 0.3 rotate x * 90 } }

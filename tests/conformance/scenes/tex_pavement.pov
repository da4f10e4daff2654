// Conformance: single-cell pavement (triangles, squares with the three
// exterior corner shapes, hexagons), two-cell tiles (dominoes, lozenges,
// hexagon pairs), straight trominoes, tiling 7 (octagons and squares) and
// tiling 4 and 5 (rhombi),
// in pigments and a normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { tiling 7 color_map { [0 rgb <0.5, 0.1, 0.1>] [0.5 rgb <1, 0.8, 0.6>] [0.5 rgb <0.3, 0.3, 0.4>] [1 rgb <0.9, 0.9, 1>] } scale 0.5 } }
sphere { <-2.6, 1, 0>, 1 pigment { tiling 4 color_map { [0 rgb <0.9, 0.4, 0.1>] [1 rgb <1, 1, 0.8>] } scale 0.3 rotate x * -60 } normal { pavement 0.5 scale 0.2 } }
disc { <0, 0.01, -3>, y, 1 pigment { pavement color_map { [0 rgb <0.2, 0.5, 0.9>] [1 rgb 1] } scale 0.4 } }
sphere { <0, 1, 0>, 1 pigment { pavement number_of_sides 6 interior 2 form 3 color_map { [0 rgb <0.8, 0.6, 0.2>] [1 rgb 0.1] } scale 0.3 rotate x * -60 } }
sphere { <2.6, 1, 0>, 1 pigment { rgb <0.7, 0.9, 0.7> } normal { pavement 0.7 number_of_sides 4 exterior 2 scale 0.35 } }
box { <-3.6, 0, 1.6>, <-1.6, 2.4, 2.4> pigment { tiling 5 color_map { [0 rgb <0.6, 0.2, 0.2>] [0.333 rgb 1] [0.333 rgb <0.2, 0.5, 0.2>] [0.667 rgb 1] [0.667 rgb <0.2, 0.2, 0.6>] [1 rgb 1] } scale 0.3 rotate x * 90 } }
box { <-1, 0, 1.6>, <1, 2.4, 2.4> pigment { pavement number_of_sides 4 exterior 1 color_map { [0 rgb <0.2, 0.6, 0.2>] [1 rgb 1] } scale 0.5 rotate x * 90 } }
box { <1.6, 0, 1.6>, <3.6, 2.4, 2.4> pigment { pavement number_of_sides 4 exterior 2 number_of_tiles 1 pattern 1 color_map { [0 rgb <0.2, 0.2, 0.6>] [1 rgb 1] } scale 0.5 rotate x * 90 } }
disc { <-2.4, 0.03, -3.2>, y, 0.7 pigment { pavement number_of_sides 4 number_of_tiles 2 exterior 2 color_map { [0 rgb <0.9, 0.5, 0.1>] [1 rgb 1] } translate <0.013, 0, 0.017> scale 0.2 } }
disc { <2.4, 0.03, -3.2>, y, 0.7 pigment { pavement number_of_tiles 2 interior 1 form 2 number_of_sides 4 color_map { [0 rgb <0.1, 0.5, 0.9>] [1 rgb 1] } translate <0.013, 0, 0.017> scale 0.2 } }
box { <-1, 2.45, 1.6>, <1, 2.5, 2.4> pigment { pavement number_of_sides 3 number_of_tiles 2 color_map { [0 rgb <0.5, 0, 0.5>] [1 rgb 1] } translate <0.013, 0, 0.017> scale 0.2 } }
disc { <0, 0.03, -3.8>, y, 0.6 pigment { pavement number_of_sides 6 number_of_tiles 2 form 3 color_map { [0 rgb <0, 0.4, 0.2>] [1 rgb 1] } translate <0.013, 0, 0.017> scale 0.15 } }
box { <1.6, 2.45, 1.6>, <3.6, 2.5, 2.4> pigment { pavement number_of_sides 4 number_of_tiles 3 interior 2 form 1 color_map { [0 rgb <0.6, 0.4, 0>] [1 rgb 1] } translate <0.013, 0, 0.017> scale 0.2 } }

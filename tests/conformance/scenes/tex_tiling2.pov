// Conformance: tilings 8 to 24 (semi-regular tilings of triangles,
// squares and hexagons, running bond, pinwheel, basketweaves, Pythagorean), one per
// object, with colour maps that separate the kinds of tile. Points exactly
// on tile edges are avoided: there povray picks tiles by its own rounding
// (tiling 12 gives 0.333313 all along z = 0).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 9, -7> color rgb 1 }
#declare Kinds3 = color_map { [0 rgb <0.6, 0.1, 0.1>] [0.333 rgb <1, 0.8, 0.7>] [0.333 rgb <0.1, 0.4, 0.1>] [0.667 rgb <0.8, 1, 0.7>] [0.667 rgb <0.1, 0.1, 0.5>] [1 rgb <0.8, 0.8, 1>] }

plane { y, 0 pigment { tiling 8 color_map { Kinds3 } scale 0.6 } }
sphere { <-2.6, 1, 0>, 1 pigment { tiling 9 color_map { Kinds3 } scale 0.3 rotate x * -60 } }
sphere { <0, 1, 0>, 1 pigment { tiling 10 color_map { [0 rgb <0.7, 0.3, 0.2>] [1 rgb 1] } scale 0.3 rotate x * -60 } }
sphere { <2.6, 1, 0>, 1 pigment { tiling 11 color_map { Kinds3 } scale 0.3 rotate x * -60 } }
box { <-3.6, 0, 1.6>, <-1.6, 2.4, 2.4> pigment { tiling 12 color_map { Kinds3 } translate <0.013, 0, 0.017> scale 0.2 rotate x * 90 } }
box { <-1, 0, 1.6>, <1, 2.4, 2.4> pigment { tiling 15 color_map { [0 rgb <0.5, 0.1, 0.1>] [0.5 rgb 1] [0.5 rgb <0.1, 0.1, 0.4>] [1 rgb <0.9, 0.9, 1>] } translate <0.013, 0, 0.017> scale 0.25 rotate x * 90 } }
box { <1.6, 0, 1.6>, <3.6, 2.4, 2.4> pigment { tiling 18 color_map { [0 rgb <0.5, 0.3, 0.1>] [0.5 rgb 1] [0.5 rgb <0.1, 0.3, 0.1>] [1 rgb <0.9, 1, 0.9>] } translate <0.013, 0, 0.017> scale 0.2 rotate x * 90 } }
disc { <0, 0.01, -2.8>, y, 1.2 pigment { tiling 16 color_map { Kinds3 } translate <0.013, 0, 0.017> scale 0.25 } }
disc { <2.6, 0.01, -2.8>, y, 1.2 pigment { tiling 22 color_map { Kinds3 } translate <0.013, 0, 0.017> scale 0.25 } }
disc { <-2.6, 0.01, -2.8>, y, 1.2 pigment { tiling 19 color_map { Kinds3 } translate <0.013, 0, 0.017> scale 0.25 } }
sphere { <0, 3.2, 1>, 0.7 pigment { tiling 20 color_map { Kinds3 } translate <0.013, 0, 0.017> scale 0.15 rotate x * -60 } }
sphere { <-2.6, 3.2, 1>, 0.7 pigment { tiling 23 color_map { Kinds3 } translate <0.013, 0, 0.017> scale 0.12 rotate x * -60 } }
sphere { <2.6, 3.2, 1>, 0.7 pigment { tiling 24 color_map { [0 rgb 0] [0.2 rgb 1] [0.2 rgb <1, 0, 0>] [0.4 rgb <1, 1, 0>] [0.4 rgb <0, 1, 0>] [0.6 rgb <0, 1, 1>] [0.6 rgb <0, 0, 1>] [0.8 rgb <1, 0, 1>] [0.8 rgb 0.5] [1 rgb 1] } translate <0.013, 0, 0.017> scale 0.12 rotate x * -60 } }
disc { <0, 0.03, -4.2>, y, 0.6 pigment { tiling 21 color_map { [0 rgb <1, 0, 0>] [0.1667 rgb <1, 1, 0>] [0.1667 rgb <0, 1, 0>] [0.3333 rgb <0, 1, 1>] [0.3333 rgb <0, 0, 1>] [0.5 rgb <1, 0, 1>] [0.5 rgb 0.3] [0.6667 rgb 1] [0.6667 rgb <0.5, 0.2, 0>] [0.8333 rgb <1, 0.6, 0.2>] [0.8333 rgb <0, 0.2, 0.5>] [1 rgb <0.3, 0.6, 1>] } translate <0.013, 0, 0.017> scale 0.2 } }
sphere { <0, 3.2, 3.5>, 0.7 pigment { tiling 17 color_map { [0 rgb <1, 0, 0>] [0.1667 rgb <1, 1, 0>] [0.1667 rgb <0, 1, 0>] [0.3333 rgb <0, 1, 1>] [0.3333 rgb <0, 0, 1>] [0.5 rgb <1, 0, 1>] [0.5 rgb 0.3] [0.6667 rgb 1] [0.6667 rgb <0.5, 0.2, 0>] [0.8333 rgb <1, 0.6, 0.2>] [0.8333 rgb <0, 0.2, 0.5>] [1 rgb <0.3, 0.6, 1>] } translate <0.013, 0, 0.017> scale 0.12 rotate x * -60 } }
sphere { <-2.6, 3.2, 3.5>, 0.7 pigment { tiling 13 color_map { Kinds3 } translate <0.013, 0, 0.017> scale 0.15 rotate x * -60 } }
sphere { <2.6, 3.2, 3.5>, 0.7 pigment { tiling 14 color_map { [0 rgb 0] [0.2 rgb 1] [0.2 rgb <1, 0, 0>] [0.4 rgb <1, 1, 0>] [0.4 rgb <0, 1, 0>] [0.6 rgb <0, 1, 1>] [0.6 rgb <0, 0, 1>] [0.8 rgb <1, 0, 1>] [0.8 rgb 0.5] [1 rgb 1] } translate <0.013, 0, 0.017> scale 0.15 rotate x * -60 } }

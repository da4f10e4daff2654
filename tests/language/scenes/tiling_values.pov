// tiling 1 (squares), 2 (hexagons), 3 (triangles), 4 and 5 (rhombi), 6 (herringbone), 7 (octagons and squares),
// 8 to 24
// and one- to three-cell pavement: pattern values read through pigment_pattern
// (povray 3.7 refuses tiling and pavement in a pattern function); 4 decimals,
// as the grey passes through single-precision colours.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare T1 = function { pattern { pigment_pattern { tiling 1 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T2 = function { pattern { pigment_pattern { tiling 2 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T3 = function { pattern { pigment_pattern { tiling 3 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T4 = function { pattern { pigment_pattern { tiling 4 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T5 = function { pattern { pigment_pattern { tiling 5 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T6 = function { pattern { pigment_pattern { tiling 6 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T7 = function { pattern { pigment_pattern { tiling 7 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T8 = function { pattern { pigment_pattern { tiling 8 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T9 = function { pattern { pigment_pattern { tiling 9 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T10 = function { pattern { pigment_pattern { tiling 10 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T11 = function { pattern { pigment_pattern { tiling 11 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T12 = function { pattern { pigment_pattern { tiling 12 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T15 = function { pattern { pigment_pattern { tiling 15 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T18 = function { pattern { pigment_pattern { tiling 18 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T16 = function { pattern { pigment_pattern { tiling 16 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T22 = function { pattern { pigment_pattern { tiling 22 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T19 = function { pattern { pigment_pattern { tiling 19 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T20 = function { pattern { pigment_pattern { tiling 20 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T23 = function { pattern { pigment_pattern { tiling 23 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T24 = function { pattern { pigment_pattern { tiling 24 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T21 = function { pattern { pigment_pattern { tiling 21 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T17 = function { pattern { pigment_pattern { tiling 17 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T13 = function { pattern { pigment_pattern { tiling 13 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T14 = function { pattern { pigment_pattern { tiling 14 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare P3 = function { pattern { pigment_pattern { pavement color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare P4 = function { pattern { pigment_pattern { pavement number_of_sides 4 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare P4r = function { pattern { pigment_pattern { pavement number_of_sides 4 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare P42 = function { pattern { pigment_pattern { pavement number_of_sides 4 number_of_tiles 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare P32 = function { pattern { pigment_pattern { pavement number_of_sides 3 number_of_tiles 2 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare P62 = function { pattern { pigment_pattern { pavement number_of_sides 6 number_of_tiles 2 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare P43 = function { pattern { pigment_pattern { pavement number_of_sides 4 number_of_tiles 3 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare P6 = function { pattern { pigment_pattern { pavement number_of_sides 6 color_map { [0 rgb 0] [1 rgb 1] } } } }
#fopen Out "tiling_values.out" write
#declare S = seed(12);
#for (I, 0, 39)
  #local X = (rand(S) - 0.5) * 8;
  #local Y = (rand(S) - 0.5) * 8;
  #local Z = (rand(S) - 0.5) * 8;
  #write (Out, str(X, 0, 4), " ", str(Z, 0, 4), ": ", str(T1(X, Y, Z), 0, 4), " ", str(T2(X, Y, Z), 0, 4), " ", str(T3(X, Y, Z), 0, 4), " ", str(T4(X, Y, Z), 0, 4), " ", str(T5(X, Y, Z), 0, 4), " ", str(T6(X, Y, Z), 0, 4), " ", str(T7(X, Y, Z), 0, 4), "\n")
  #write (Out, "  tilings 8 to 24: ", str(T8(X, Y, Z), 0, 4), " ", str(T9(X, Y, Z), 0, 4), " ", str(T10(X, Y, Z), 0, 4), " ", str(T11(X, Y, Z), 0, 4), " ", str(T12(X, Y, Z), 0, 4), " ", str(T13(X, Y, Z), 0, 4), " ", str(T14(X, Y, Z), 0, 4), " ", str(T15(X, Y, Z), 0, 4), " ", str(T16(X, Y, Z), 0, 4), " ", str(T17(X, Y, Z), 0, 4), " ", str(T18(X, Y, Z), 0, 4), " ", str(T19(X, Y, Z), 0, 4), " ", str(T20(X, Y, Z), 0, 4), " ", str(T21(X, Y, Z), 0, 4), " ", str(T22(X, Y, Z), 0, 4), " ", str(T23(X, Y, Z), 0, 4), " ", str(T24(X, Y, Z), 0, 4), "\n")
  #write (Out, "  pavement ", str(P3(X, Y, Z), 0, 4), " ", str(P4(X, Y, Z), 0, 4), " ", str(P4r(X, Y, Z), 0, 4), " ", str(P6(X, Y, Z), 0, 4), " ", str(P42(X, Y, Z), 0, 4), " ", str(P32(X, Y, Z), 0, 4), " ", str(P62(X, Y, Z), 0, 4), " ", str(P43(X, Y, Z), 0, 4), "\n")
#end
#fclose Out

// tiling 1 (squares), 2 (hexagons) and 3 (triangles): pattern values read
// through pigment_pattern (povray 3.7 refuses tiling in a pattern function).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare T1 = function { pattern { pigment_pattern { tiling 1 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T2 = function { pattern { pigment_pattern { tiling 2 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare T3 = function { pattern { pigment_pattern { tiling 3 color_map { [0 rgb 0] [1 rgb 1] } } } }
#fopen Out "tiling_values.out" write
#declare S = seed(11);
#for (I, 0, 39)
  #local X = (rand(S) - 0.5) * 8;
  #local Y = (rand(S) - 0.5) * 8;
  #local Z = (rand(S) - 0.5) * 8;
  #write (Out, str(X, 0, 4), " ", str(Z, 0, 4), ": ", str(T1(X, Y, Z), 0, 5), " ", str(T2(X, Y, Z), 0, 5), " ", str(T3(X, Y, Z), 0, 5), "\n")
#end
#fclose Out

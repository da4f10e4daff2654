#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare F = function { pattern { pigment_pattern { pavement number_of_sides 6 number_of_tiles 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare S = seed(7);
#for (I, 0, 399)
  #local X = (rand(S) - 0.5) * 12; #local Z = (rand(S) - 0.5) * 12;
  #debug concat(str(X,0,6), " ", str(Z,0,6), " : ", str(F(X, 0, Z), 0, 6), "\n")
#end

// Language test: a height_field function whose body is a pigment takes the
// colour's gray (0.297 red + 0.589 green + 0.114 blue) as the height, as
// povray 3.7 reads the example advanced/landscape.pov. Heights are read
// back with trace().
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "height_field_pigment_function.out" write
#macro Height(P)
  #local H = height_field { function 4, 4 { pigment { P } } }
  #local Hit = trace(H, <0.5, 10, 0.5>, -y);
  str(Hit.y, 0, 4)
#end
#write (Out, "red ", Height(rgb <1, 0, 0>), "\n")
#write (Out, "green ", Height(rgb <0, 1, 0>), "\n")
#write (Out, "blue ", Height(rgb <0, 0, 1>), "\n")
#write (Out, "grey ", Height(rgb 0.5), "\n")
#write (Out, "transmit ", Height(rgbt <0.2, 0.4, 0.6, 0.5>), "\n")
// A pattern: gradient x runs across the field.
#declare G = height_field { function 11, 11 { pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } } }
#declare A = trace(G, <0.3, 10, 0.5>, -y);
#declare B = trace(G, <0.7, 10, 0.5>, -y);
#write (Out, "gradient ", str(A.y, 0, 4), " ", str(B.y, 0, 4), "\n")
#fclose Out

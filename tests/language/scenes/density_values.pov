// density_file df3 values through pattern functions: 8 and 16-bit files
// of 3 x 2 x 4 random samples (density_values_*.df3), interpolate 0, 1
// and 2, points inside and outside the unit cube. Interpolation 2 prints
// 5 digits: povray computes it in single precision.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare F0 = function { pattern { density_file df3 "density_values_8bit.df3" } }
#declare F1 = function { pattern { density_file df3 "density_values_8bit.df3" interpolate 1 } }
#declare F2 = function { pattern { density_file df3 "density_values_8bit.df3" interpolate 2 } }
#declare G0 = function { pattern { density_file df3 "density_values_16bit.df3" } }
#declare G1 = function { pattern { density_file df3 "density_values_16bit.df3" interpolate 1 } }
#declare G2 = function { pattern { density_file df3 "density_values_16bit.df3" interpolate 2 frequency 2 } }
#declare S = seed(1);
#fopen Out "density_values.out" write
#for (I, 0, 59)
  #local P = <rand(S) * 1.4 - 0.2, rand(S) * 1.4 - 0.2, rand(S) * 1.4 - 0.2>;
  #write (Out, "point ", I, ": ", str(F0(P.x, P.y, P.z), 0, 12), " ", str(F1(P.x, P.y, P.z), 0, 12), " ",
          str(F2(P.x, P.y, P.z), 0, 5), " ", str(G0(P.x, P.y, P.z), 0, 12), " ", str(G1(P.x, P.y, P.z), 0, 12), " ",
          str(G2(P.x, P.y, P.z), 0, 5), "\n")
#end
#fclose Out

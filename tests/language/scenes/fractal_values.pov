// mandel and julia values through pattern functions: escape iteration over
// the iteration count, exponents, exterior type 0 and the interior factor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare M = function { pattern { mandel 30 } }
#declare J = function { pattern { julia <0.353, 0.288>, 30 } }
#declare M3 = function { pattern { mandel 25 exponent 3 } }
#declare J4 = function { pattern { julia <-0.4, 0.6>, 40 exponent 4 interior 0, 0.3 } }
#declare E0 = function { pattern { mandel 30 exterior 0, 0.7 } }
#declare S = seed(2);
#fopen Out "fractal_values.out" write
#for (I, 0, 29)
  #local P = <rand(S) * 3 - 2, rand(S) * 2.4 - 1.2, rand(S)>;
  #write (Out, "point ", I, ": mandel ", str(M(P.x, P.y, P.z), 0, 6), " julia ", str(J(P.x, P.y, P.z), 0, 6),
          " mandel3 ", str(M3(P.x, P.y, P.z), 0, 6), " julia4 ", str(J4(P.x, P.y, P.z), 0, 6),
          " exterior0 ", str(E0(P.x, P.y, P.z), 0, 6), "\n")
#end
#fclose Out

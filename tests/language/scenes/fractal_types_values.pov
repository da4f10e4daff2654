// Fractal colouring types and the magnet fractals through pattern functions:
// interior and exterior types 0 to 6 with a factor on mandel, julia and
// magnet 1/2 (mandel and julia forms), at random points of the plane.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Md0 = function { pattern { mandel 30 interior 0, 0.7 exterior 0, 0.6 } }
#declare Md1 = function { pattern { mandel 30 interior 1, 0.7 exterior 1, 0.6 } }
#declare Md2 = function { pattern { mandel 30 interior 2, 0.7 exterior 2, 0.6 } }
#declare Md3 = function { pattern { mandel 30 interior 3, 0.7 exterior 3, 0.6 } }
#declare Md4 = function { pattern { mandel 30 interior 4, 0.7 exterior 4, 0.6 } }
#declare Md5 = function { pattern { mandel 30 interior 5, 0.7 exterior 5, 0.6 } }
#declare Md6 = function { pattern { mandel 30 interior 6, 0.7 exterior 6, 0.6 } }
#declare Ju0 = function { pattern { julia <-0.7, 0.3>, 30 interior 0, 0.7 exterior 0, 0.6 } }
#declare Ju1 = function { pattern { julia <-0.7, 0.3>, 30 interior 1, 0.7 exterior 1, 0.6 } }
#declare Ju2 = function { pattern { julia <-0.7, 0.3>, 30 interior 2, 0.7 exterior 2, 0.6 } }
#declare Ju3 = function { pattern { julia <-0.7, 0.3>, 30 interior 3, 0.7 exterior 3, 0.6 } }
#declare Ju4 = function { pattern { julia <-0.7, 0.3>, 30 interior 4, 0.7 exterior 4, 0.6 } }
#declare Ju5 = function { pattern { julia <-0.7, 0.3>, 30 interior 5, 0.7 exterior 5, 0.6 } }
#declare Ju6 = function { pattern { julia <-0.7, 0.3>, 30 interior 6, 0.7 exterior 6, 0.6 } }
#declare M1m0 = function { pattern { magnet 1 mandel 25 interior 0, 0.7 exterior 0, 0.6 } }
#declare M1m1 = function { pattern { magnet 1 mandel 25 interior 1, 0.7 exterior 1, 0.6 } }
#declare M1m2 = function { pattern { magnet 1 mandel 25 interior 2, 0.7 exterior 2, 0.6 } }
#declare M1m3 = function { pattern { magnet 1 mandel 25 interior 3, 0.7 exterior 3, 0.6 } }
#declare M1m4 = function { pattern { magnet 1 mandel 25 interior 4, 0.7 exterior 4, 0.6 } }
#declare M1m5 = function { pattern { magnet 1 mandel 25 interior 5, 0.7 exterior 5, 0.6 } }
#declare M1m6 = function { pattern { magnet 1 mandel 25 interior 6, 0.7 exterior 6, 0.6 } }
#declare M1j0 = function { pattern { magnet 1 julia <0.3, 0.4>, 25 interior 0, 0.7 exterior 0, 0.6 } }
#declare M1j1 = function { pattern { magnet 1 julia <0.3, 0.4>, 25 interior 1, 0.7 exterior 1, 0.6 } }
#declare M1j2 = function { pattern { magnet 1 julia <0.3, 0.4>, 25 interior 2, 0.7 exterior 2, 0.6 } }
#declare M1j3 = function { pattern { magnet 1 julia <0.3, 0.4>, 25 interior 3, 0.7 exterior 3, 0.6 } }
#declare M1j4 = function { pattern { magnet 1 julia <0.3, 0.4>, 25 interior 4, 0.7 exterior 4, 0.6 } }
#declare M1j5 = function { pattern { magnet 1 julia <0.3, 0.4>, 25 interior 5, 0.7 exterior 5, 0.6 } }
#declare M1j6 = function { pattern { magnet 1 julia <0.3, 0.4>, 25 interior 6, 0.7 exterior 6, 0.6 } }
#declare M2m0 = function { pattern { magnet 2 mandel 25 interior 0, 0.7 exterior 0, 0.6 } }
#declare M2m1 = function { pattern { magnet 2 mandel 25 interior 1, 0.7 exterior 1, 0.6 } }
#declare M2m2 = function { pattern { magnet 2 mandel 25 interior 2, 0.7 exterior 2, 0.6 } }
#declare M2m3 = function { pattern { magnet 2 mandel 25 interior 3, 0.7 exterior 3, 0.6 } }
#declare M2m4 = function { pattern { magnet 2 mandel 25 interior 4, 0.7 exterior 4, 0.6 } }
#declare M2m5 = function { pattern { magnet 2 mandel 25 interior 5, 0.7 exterior 5, 0.6 } }
#declare M2m6 = function { pattern { magnet 2 mandel 25 interior 6, 0.7 exterior 6, 0.6 } }
#declare M2j0 = function { pattern { magnet 2 julia <0.3, 0.4>, 25 interior 0, 0.7 exterior 0, 0.6 } }
#declare M2j1 = function { pattern { magnet 2 julia <0.3, 0.4>, 25 interior 1, 0.7 exterior 1, 0.6 } }
#declare M2j2 = function { pattern { magnet 2 julia <0.3, 0.4>, 25 interior 2, 0.7 exterior 2, 0.6 } }
#declare M2j3 = function { pattern { magnet 2 julia <0.3, 0.4>, 25 interior 3, 0.7 exterior 3, 0.6 } }
#declare M2j4 = function { pattern { magnet 2 julia <0.3, 0.4>, 25 interior 4, 0.7 exterior 4, 0.6 } }
#declare M2j5 = function { pattern { magnet 2 julia <0.3, 0.4>, 25 interior 5, 0.7 exterior 5, 0.6 } }
#declare M2j6 = function { pattern { magnet 2 julia <0.3, 0.4>, 25 interior 6, 0.7 exterior 6, 0.6 } }
#declare S = seed(4);
#fopen Out "fractal_types_values.out" write
#for (I, 0, 39)
  #local P = <rand(S) * 4 - 2, rand(S) * 4 - 2, 0>;
  #write (Out, "point ", I, ":")
  #write (Out, " md", " ", str(Md0(P.x, P.y, 0), 0, 6), " ", str(Md1(P.x, P.y, 0), 0, 6), " ", str(Md2(P.x, P.y, 0), 0, 6), " ", str(Md3(P.x, P.y, 0), 0, 6), " ", str(Md4(P.x, P.y, 0), 0, 6), " ", str(Md5(P.x, P.y, 0), 0, 6), " ", str(Md6(P.x, P.y, 0), 0, 6))
  #write (Out, " ju", " ", str(Ju0(P.x, P.y, 0), 0, 6), " ", str(Ju1(P.x, P.y, 0), 0, 6), " ", str(Ju2(P.x, P.y, 0), 0, 6), " ", str(Ju3(P.x, P.y, 0), 0, 6), " ", str(Ju4(P.x, P.y, 0), 0, 6), " ", str(Ju5(P.x, P.y, 0), 0, 6), " ", str(Ju6(P.x, P.y, 0), 0, 6))
  #write (Out, " m1m", " ", str(M1m0(P.x, P.y, 0), 0, 6), " ", str(M1m1(P.x, P.y, 0), 0, 6), " ", str(M1m2(P.x, P.y, 0), 0, 6), " ", str(M1m3(P.x, P.y, 0), 0, 6), " ", str(M1m4(P.x, P.y, 0), 0, 6), " ", str(M1m5(P.x, P.y, 0), 0, 6), " ", str(M1m6(P.x, P.y, 0), 0, 6))
  #write (Out, " m1j", " ", str(M1j0(P.x, P.y, 0), 0, 6), " ", str(M1j1(P.x, P.y, 0), 0, 6), " ", str(M1j2(P.x, P.y, 0), 0, 6), " ", str(M1j3(P.x, P.y, 0), 0, 6), " ", str(M1j4(P.x, P.y, 0), 0, 6), " ", str(M1j5(P.x, P.y, 0), 0, 6), " ", str(M1j6(P.x, P.y, 0), 0, 6))
  #write (Out, " m2m", " ", str(M2m0(P.x, P.y, 0), 0, 6), " ", str(M2m1(P.x, P.y, 0), 0, 6), " ", str(M2m2(P.x, P.y, 0), 0, 6), " ", str(M2m3(P.x, P.y, 0), 0, 6), " ", str(M2m4(P.x, P.y, 0), 0, 6), " ", str(M2m5(P.x, P.y, 0), 0, 6), " ", str(M2m6(P.x, P.y, 0), 0, 6))
  #write (Out, " m2j", " ", str(M2j0(P.x, P.y, 0), 0, 6), " ", str(M2j1(P.x, P.y, 0), 0, 6), " ", str(M2j2(P.x, P.y, 0), 0, 6), " ", str(M2j3(P.x, P.y, 0), 0, 6), " ", str(M2j4(P.x, P.y, 0), 0, 6), " ", str(M2j5(P.x, P.y, 0), 0, 6), " ", str(M2j6(P.x, P.y, 0), 0, 6))
  #write (Out, "\n")
#end
#fclose Out

// warp { cylindrical | spherical | toroidal | planar } with orientation,
// dist_exp and major_radius: the warped point, read through gradient
// functions placed before the warp (values measured from povray 3.7).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "warp_mapping_values.out" write
#declare Pts = array[7] { <0.3, 0.2, 0.7>, <-0.5, 1.2, 0.25>, <1.5, -0.7, -0.4>, <-2, 0.3, -1.1>, <0, 0.4, 0>, <0.5, 0, 0>, <-1.5, 0, 0> }
#declare FX1 = function { pattern { gradient x scale 1000 translate -500 * x warp { cylindrical } } }
#declare FY1 = function { pattern { gradient y scale 1000 translate -500 * y warp { cylindrical } } }
#declare FZ1 = function { pattern { gradient z scale 1000 translate -500 * z warp { cylindrical } } }
#write (Out, "warp { cylindrical }\n")
#for (I, 0, 6)
  #declare P = Pts[I];
  #write (Out, "  ", str(FX1(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FY1(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FZ1(P.x, P.y, P.z) * 1000 - 500, 0, 6), "\n")
#end
#declare FX2 = function { pattern { gradient x scale 1000 translate -500 * x warp { cylindrical dist_exp 2 } } }
#declare FY2 = function { pattern { gradient y scale 1000 translate -500 * y warp { cylindrical dist_exp 2 } } }
#declare FZ2 = function { pattern { gradient z scale 1000 translate -500 * z warp { cylindrical dist_exp 2 } } }
#write (Out, "warp { cylindrical dist_exp 2 }\n")
#for (I, 0, 6)
  #declare P = Pts[I];
  #write (Out, "  ", str(FX2(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FY2(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FZ2(P.x, P.y, P.z) * 1000 - 500, 0, 6), "\n")
#end
#declare FX3 = function { pattern { gradient x scale 1000 translate -500 * x warp { cylindrical orientation <1, 2, 3> } } }
#declare FY3 = function { pattern { gradient y scale 1000 translate -500 * y warp { cylindrical orientation <1, 2, 3> } } }
#declare FZ3 = function { pattern { gradient z scale 1000 translate -500 * z warp { cylindrical orientation <1, 2, 3> } } }
#write (Out, "warp { cylindrical orientation <1, 2, 3> }\n")
#for (I, 0, 6)
  #declare P = Pts[I];
  #write (Out, "  ", str(FX3(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FY3(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FZ3(P.x, P.y, P.z) * 1000 - 500, 0, 6), "\n")
#end
#declare FX4 = function { pattern { gradient x scale 1000 translate -500 * x warp { spherical } } }
#declare FY4 = function { pattern { gradient y scale 1000 translate -500 * y warp { spherical } } }
#declare FZ4 = function { pattern { gradient z scale 1000 translate -500 * z warp { spherical } } }
#write (Out, "warp { spherical }\n")
#for (I, 0, 6)
  #declare P = Pts[I];
  #write (Out, "  ", str(FX4(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FY4(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FZ4(P.x, P.y, P.z) * 1000 - 500, 0, 6), "\n")
#end
#declare FX5 = function { pattern { gradient x scale 1000 translate -500 * x warp { spherical dist_exp 1.5 orientation y } } }
#declare FY5 = function { pattern { gradient y scale 1000 translate -500 * y warp { spherical dist_exp 1.5 orientation y } } }
#declare FZ5 = function { pattern { gradient z scale 1000 translate -500 * z warp { spherical dist_exp 1.5 orientation y } } }
#write (Out, "warp { spherical dist_exp 1.5 orientation y }\n")
#for (I, 0, 6)
  #declare P = Pts[I];
  #write (Out, "  ", str(FX5(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FY5(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FZ5(P.x, P.y, P.z) * 1000 - 500, 0, 6), "\n")
#end
#declare FX6 = function { pattern { gradient x scale 1000 translate -500 * x warp { toroidal } } }
#declare FY6 = function { pattern { gradient y scale 1000 translate -500 * y warp { toroidal } } }
#declare FZ6 = function { pattern { gradient z scale 1000 translate -500 * z warp { toroidal } } }
#write (Out, "warp { toroidal }\n")
#for (I, 0, 6)
  #declare P = Pts[I];
  #write (Out, "  ", str(FX6(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FY6(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FZ6(P.x, P.y, P.z) * 1000 - 500, 0, 6), "\n")
#end
#declare FX7 = function { pattern { gradient x scale 1000 translate -500 * x warp { toroidal major_radius 2 dist_exp 0.5 orientation <0, 1, 1> } } }
#declare FY7 = function { pattern { gradient y scale 1000 translate -500 * y warp { toroidal major_radius 2 dist_exp 0.5 orientation <0, 1, 1> } } }
#declare FZ7 = function { pattern { gradient z scale 1000 translate -500 * z warp { toroidal major_radius 2 dist_exp 0.5 orientation <0, 1, 1> } } }
#write (Out, "warp { toroidal major_radius 2 dist_exp 0.5 orientation <0, 1, 1> }\n")
#for (I, 0, 6)
  #declare P = Pts[I];
  #write (Out, "  ", str(FX7(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FY7(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FZ7(P.x, P.y, P.z) * 1000 - 500, 0, 6), "\n")
#end
#declare FX8 = function { pattern { gradient x scale 1000 translate -500 * x warp { planar } } }
#declare FY8 = function { pattern { gradient y scale 1000 translate -500 * y warp { planar } } }
#declare FZ8 = function { pattern { gradient z scale 1000 translate -500 * z warp { planar } } }
#write (Out, "warp { planar }\n")
#for (I, 0, 6)
  #declare P = Pts[I];
  #write (Out, "  ", str(FX8(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FY8(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FZ8(P.x, P.y, P.z) * 1000 - 500, 0, 6), "\n")
#end
#declare FX9 = function { pattern { gradient x scale 1000 translate -500 * x warp { planar <1, 2, 3>, 0.3 } } }
#declare FY9 = function { pattern { gradient y scale 1000 translate -500 * y warp { planar <1, 2, 3>, 0.3 } } }
#declare FZ9 = function { pattern { gradient z scale 1000 translate -500 * z warp { planar <1, 2, 3>, 0.3 } } }
#write (Out, "warp { planar <1, 2, 3>, 0.3 }\n")
#for (I, 0, 6)
  #declare P = Pts[I];
  #write (Out, "  ", str(FX9(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FY9(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FZ9(P.x, P.y, P.z) * 1000 - 500, 0, 6), "\n")
#end
#declare FX10 = function { pattern { gradient x scale 1000 translate -500 * x warp { cylindrical orientation -z } } }
#declare FY10 = function { pattern { gradient y scale 1000 translate -500 * y warp { cylindrical orientation -z } } }
#declare FZ10 = function { pattern { gradient z scale 1000 translate -500 * z warp { cylindrical orientation -z } } }
#write (Out, "warp { cylindrical orientation -z }\n")
#for (I, 0, 6)
  #declare P = Pts[I];
  #write (Out, "  ", str(FX10(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FY10(P.x, P.y, P.z) * 1000 - 500, 0, 6), " ", str(FZ10(P.x, P.y, P.z) * 1000 - 500, 0, 6), "\n")
#end
#fclose Out

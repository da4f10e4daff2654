// function { pattern { ... } }: colour-list patterns give their index,
// mapped patterns their value after frequency, phase and the wave;
// functions.inc's pattern functions and internals called at parse time.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
#declare Checker = function { pattern { checker } }
#declare Hexagon = function { pattern { hexagon } }
#declare Brick = function { pattern { brick scale 0.5 } }
#declare Gradient = function { pattern { gradient x } }
#declare Gradient2 = function { pattern { gradient x frequency 2 phase 0.1 } }
#declare Triangle = function { pattern { gradient x triangle_wave } }
#declare Bozo = function { pattern { bozo scale 0.3 } }
#declare Turbulent = function { pattern { spherical turbulence 0.4 octaves 3 } }
#declare Outer = function { Gradient(x, y, z) * 2 + f_sphere(x, y, z, 1) }
#fopen Out "pattern_functions.out" write
#for (I, 0, 9)
  #local P = <I * 0.37 - 1.6, I * 0.11, I * 0.23 - 0.9>;
  #write (Out, "point ", I, ": checker ", Checker(P.x, P.y, P.z), " hexagon ", Hexagon(P.x, P.y, P.z),
          " brick ", Brick(P.x, P.y, P.z), "\n")
  #write (Out, "  gradient ", str(Gradient(P.x, P.y, P.z), 0, 6), " ", str(Gradient2(P.x, P.y, P.z), 0, 6),
          " triangle ", str(Triangle(P.x, P.y, P.z), 0, 6), "\n")
  #write (Out, "  bozo ", str(Bozo(P.x, P.y, P.z), 0, 6), " turbulent ", str(Turbulent(P.x, P.y, P.z), 0, 6),
          " outer ", str(Outer(P.x, P.y, P.z), 0, 6), "\n")
  #write (Out, "  f_granite ", str(f_granite(P.x, P.y, P.z), 0, 6), " f_wood ", str(f_wood(P.x, P.y, P.z), 0, 6),
          " f_noise3d ", str(f_noise3d(P.x, P.y, P.z), 0, 6), " f_snoise3d ", str(f_snoise3d(P.x, P.y, P.z), 0, 6), "\n")
  #write (Out, "  f_torus ", str(f_torus(P.x, P.y, P.z, 1, 0.3), 0, 6), " f_rounded_box ",
          str(f_rounded_box(P.x, P.y, P.z, 0.2, 1, 0.5, 0.7), 0, 6), " f_th ", str(f_th(P.x, P.y, P.z), 0, 6),
          " f_ph ", str(f_ph(P.x, P.y, P.z), 0, 6), "\n")
#end
#fclose Out

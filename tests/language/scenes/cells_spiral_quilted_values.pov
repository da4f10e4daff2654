// Values of cells, quilted, spiral1 and spiral2 at parse time through
// pattern functions: random points, cube boundaries (cells nudges by 1e-10),
// quilted's controls, spiral arms (truncated, negative), the spirals'
// default triangle wave, ramp_wave, frequency and phase, and the z axis.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Cells = function { pattern { cells } }
#declare CellsF = function { pattern { cells frequency 3 phase 0.2 } }
#declare Quilt = function { pattern { quilted } }
#declare QuiltC = function { pattern { quilted control0 0.3 control1 0.8 } }
#declare QuiltN = function { pattern { quilted control0 -1 control1 2 } }
#declare S1 = function { pattern { spiral1 3 } }
#declare S1R = function { pattern { spiral1 2.7 ramp_wave } }
#declare S1N = function { pattern { spiral1 -2 frequency 2 phase 0.1 } }
#declare S2 = function { pattern { spiral2 3 } }
#declare S2R = function { pattern { spiral2 1 ramp_wave } }
#declare S2N = function { pattern { spiral2 -4 sine_wave } }
#declare S = seed(7);
#fopen Out "cells_spiral_quilted_values.out" write
#for (I, 0, 29)
  #local P = <rand(S) * 40 - 20, rand(S) * 40 - 20, rand(S) * 40 - 20>;
  #write (Out, "point ", I, ": cells ", str(Cells(P.x, P.y, P.z), 0, 9), " cellsf ", str(CellsF(P.x, P.y, P.z), 0, 9),
          " quilt ", str(Quilt(P.x, P.y, P.z), 0, 9), " quiltc ", str(QuiltC(P.x, P.y, P.z), 0, 9),
          " quiltn ", str(QuiltN(P.x, P.y, P.z), 0, 9), "\n")
  #write (Out, "  spirals: ", str(S1(P.x, P.y, P.z), 0, 9), " ", str(S1R(P.x, P.y, P.z), 0, 9), " ",
          str(S1N(P.x, P.y, P.z), 0, 9), " ", str(S2(P.x, P.y, P.z), 0, 9), " ", str(S2R(P.x, P.y, P.z), 0, 9), " ",
          str(S2N(P.x, P.y, P.z), 0, 9), "\n")
#end
#write (Out, "cells boundary: ", str(Cells(0, 0, 0), 0, 9), " ", str(Cells(-5e-11, 0, 0), 0, 9), " ",
        str(Cells(0, -2e-10, 0), 0, 9), " ", str(Cells(0, 0, -1e-9), 0, 9), " ", str(Cells(4096, 1, 2), 0, 9), " ",
        str(Cells(0, 1, 2), 0, 9), "\n")
#write (Out, "axis: ", str(S1(0, 0, 0.3), 0, 9), " ", str(S2(0, 0, 0.3), 0, 9), " ", str(S2R(0, 0, 0), 0, 9), " ",
        str(S1R(-1, 0, 0), 0, 9), " ", str(S1R(0, -1, 0), 0, 9), " ", str(S1R(0, 1, 0), 0, 9), "\n")
#fclose Out

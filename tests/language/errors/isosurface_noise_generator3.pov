// A functions.inc noise function given noise generator 3 (Perlin), which
// frameray lacks: refused when the isosurface's function is parsed, since an
// error mid-render could not be reported.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
isosurface { function { f_ridged_mf(x, y, z, 0.5, 2, 4, 1, 2, 3) - 1 } contained_by { box { -1, 1 } } }

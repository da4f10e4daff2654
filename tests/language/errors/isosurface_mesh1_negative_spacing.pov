// f_mesh1 with a negative thread distance: povray's values were not
// matched, so frameray refuses it when the function is parsed.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
isosurface { function { f_mesh1(x, y, z, -0.5, 1, 1, 0.2, 1) - 0.1 } contained_by { box { -1, 1 } } }

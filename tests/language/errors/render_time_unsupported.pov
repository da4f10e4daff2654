// Error test: an isosurface whose function reaches something unsupported
// only while rendering (the thread distance comes through a parameter, so
// the parser cannot see it). The error must end the frame, not vanish inside
// Embree and leave the object silently missing.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "functions.inc"
camera { location <0, 0, -4> look_at 0 }
light_source { <2, 4, -5> rgb 1 }
#declare G = function(x, y, z, d) { f_mesh1(x, y, z, d, d, 1, 0.1, 1) }
#declare Distance = 0;
isosurface { function { f_sphere(x, y, z, 1) - G(x, y, z, Distance) * 0.2 } contained_by { box { -2, 2 } } pigment { rgb 1 } }

// functions.inc internals (f_rounded_box, f_sphere, f_noise3d, f_torus,
// f_superellipsoid, f_ph, f_th, f_ellipsoid) and pattern functions
// (f_granite) in isosurfaces and function pigments.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1 }
camera { location <0,2,-5> look_at 0 angle 45 }
light_source { <-5,10,-10> color rgb 1 }
isosurface { function { f_rounded_box(x,y,z,0.2,0.8,0.5,0.6) } contained_by { box { -1, 1 } } max_gradient 1.1
  pigment { function { f_granite(x,y,z) } color_map { [0 rgb <1,0.5,0>] [1 rgb <0,0.3,1>] } } translate -x*1.2 }
isosurface { function { f_sphere(x,y,z,0.8) - f_noise3d(x*4,y*4,z*4)*0.3 + f_torus(x,y,z,0.6,0.1)*0 } contained_by { sphere { 0, 1.2 } } max_gradient 3
  pigment { function { f_ph(x,y,z)/pi } color_map { [0 rgb <1,1,0>] [1 rgb <0,0,1>] } } translate x*1.2 }
isosurface { function { 0.5 - f_superellipsoid(x,y,z,0.3,0.6) } contained_by { box { -1.1, 1.1 } } max_gradient 4 scale 0.5
  pigment { function { f_th(x,y,z)/(2*pi)+0.5 } color_map { [0 rgb 1] [1 rgb <0,0.6,0>] } } translate <0,1.3,1> }
plane { y, -1 pigment { function { f_ellipsoid(x,0,z,1,2,1) } } }

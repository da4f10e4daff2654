// Conformance: noise_generator 3 (povray's Perlin-style noise) in bozo,
// wrinkles, agate, granite, marble turbulence, dents normals, a turbulence
// warp, f_noise3d under global_settings and an isosurface of
// f_noise_generator(..., 3).
#version 3.7;
global_settings { assumed_gamma 1.0 noise_generator 3 }
#include "functions.inc"
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 60 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { granite scale 3 color_map { [0 rgb <0.9, 0.8, 0.6>] [1 rgb <0.2, 0.1, 0.1>] } } }
sphere { <-3, 1, 0>, 1 pigment { bozo scale 0.3 color_map { [0 rgb 0] [1 rgb 1] } } }
sphere { <-1, 1, 0>, 1 pigment { wrinkles noise_generator 3 scale 0.3 color_map { [0 rgb <1, 0.2, 0>] [1 rgb <0, 0.3, 1>] } } }
sphere { <1, 1, 0>, 1 pigment { agate scale 0.5 } }
sphere { <3, 1, 0>, 1 pigment { marble turbulence 0.8 scale 0.5 color_map { [0 rgb 1] [1 rgb <0.2, 0.5, 0.2>] } } }
sphere { <-2, 1, 2.5>, 1 pigment { rgb <0.9, 0.7, 0.4> } normal { dents 0.8 noise_generator 3 scale 0.2 } }
sphere { <0, 1, 2.5>, 1 pigment { function { f_noise3d(x * 3, y * 3, z * 3) } color_map { [0 rgb <0, 0, 0.5>] [1 rgb <1, 1, 0.5>] } } }
box { <1.2, 0, 1.7>, <2.8, 1.6, 3.3> pigment { checker rgb 1 rgb <0.3, 0.3, 0.6> warp { turbulence 0.5 } scale 0.4 } }
isosurface {
  function { f_sphere(x, y, z, 0.9) - f_noise_generator(x * 2, y * 2, z * 2, 3) * 0.5 }
  contained_by { sphere { 0, 1.2 } } max_gradient 2.2
  pigment { rgb <0.8, 0.4, 0.6> } translate <4.2, 1.2, 2.5>
}

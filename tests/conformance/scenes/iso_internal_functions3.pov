// functions.inc's f_comma and f_helical_torus in isosurfaces: a comma
// (scale 1) and a helical torus with eight twisted windings (grooves make the
// gradient too steep for a quick render; the language test covers them).
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1 }
camera { location <0,2.5,-6> look_at <0,0.2,0> angle 45 }
light_source { <-5,10,-10> color rgb 1 }
light_source { <6,4,-3> color rgb 0.4 }
isosurface {
  function { f_comma(x,y,z, 1) }
  contained_by { box { -1.1, 1.1 } } max_gradient 4
  pigment { rgb <1,0.75,0.2> } finish { phong 0.6 }
  rotate <-70,20,0> scale 1.2 translate <-1.5,0.3,0>
}
isosurface {
  function { f_helical_torus(x,y,z, 1, 8, 1, 0.12, 0, 0.3, 0.0156, 0, 0, 0) }
  contained_by { box { <-1.5,-0.6,-1.5>, <1.5,0.6,1.5> } } max_gradient 4
  pigment { rgb <0.2,0.55,1> } finish { phong 0.6 }
  rotate <-30,0,0> translate <1.4,0.2,0>
}
plane { y, -1.2 pigment { checker rgb 0.8 rgb 0.5 } }

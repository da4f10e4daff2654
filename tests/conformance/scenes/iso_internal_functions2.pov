// More functions.inc internals in isosurfaces, with parameters from
// povray's Isosurfaces_by_function_inc templates: f_helix1 (8 helixes,
// diamond cross-section), f_spikes on a sphere, f_torus2 (field strength,
// threshold), f_spiral, f_heart.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1 }
camera { location <0,2.5,-6> look_at <0,0.4,0> angle 50 }
light_source { <-5,10,-10> color rgb 1 }
light_source { <6,4,-3> color rgb 0.4 }
isosurface {
  function { f_helix1(x,y,z, 8, 4, 0.07, 0.8, 0.75, 2, 0) }
  contained_by { box { -1, 1 } } max_gradient 8
  pigment { rgb <0.9,0.8,0.3> } finish { phong 0.5 }
  scale 0.9 translate <-2,0.9,0.5>
}
isosurface {
  function { f_sphere(x,y,z,0.85) + f_spikes(x,y,z, 0.0001, 1.34, 0.95, 0.7, 1) }
  contained_by { box { -2, 2 } } threshold 1.55 max_gradient 8
  pigment { rgb <1,0.15,0.3> } finish { phong 0.7 }
  rotate <-40,10,0> scale 0.65 translate <0,1.1,0.5>
}
isosurface {
  function { f_torus2(x,y,z, -0.75, 0.65, 0.02) }
  contained_by { box { -1, 1 } } threshold 0.16 max_gradient 12
  pigment { rgb <0.2,0.5,1> } finish { phong 0.5 }
  rotate <-40,20,0> scale 1.2 translate <2,0.9,0.5>
}
isosurface {
  function { f_spiral(x,y,z, 0.2, 0.05, 0.9, 0, 0, 0.75) }
  contained_by { sphere { 0, 1 } } max_gradient 6
  pigment { rgb <1,0.75,0> } finish { phong 0.7 }
  rotate <90,0,0> scale 1.1 translate <-1,-0.6,-1>
}
isosurface {
  function { f_heart(x,y,z, -0.15) }
  accuracy 0.0001 max_gradient 100
  contained_by { box { <-1.1,-1.5,-1.1>, <1.1,1.22,1.5> } }
  pigment { rgb <0.9,0.1,0.1> } finish { phong 0.6 }
  rotate <-90,0,0> scale 0.55 translate <1.2,-0.5,-1>
}
plane { y, -1.2 pigment { checker rgb 0.8 rgb 0.5 } }

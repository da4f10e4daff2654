// Conformance: povray reads the commas between an object's parameters as
// optional (torus radii, blob components, prism heights, sphere_sweep
// spheres, parametric corners, macro arguments), silently. Example scenes
// write `torus { 2 .1 }` and `M(<1,0,0> .5)`.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <5, 8, -6> rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.5 } }
torus { 1.6 .25 pigment { rgb <1, 0.6, 0.2> } }
blob {
  threshold .5
  sphere { <0,0,0> 1 1 }
  cylinder { <-1,0,0> <1,0,0> .4 1 }
  pigment { rgb <0.3, 0.5, 1> }
  translate <-2.6, 0, 1.5>
}
prism {
  linear_sweep linear_spline 0 .8 4 <0,0> <1,0> <0,1> <0,0>
  pigment { rgb <0.3, 1, 0.4> }
  translate <2, -1, 1>
}
sphere_sweep {
  linear_spline 2 <-1, -0.7, -2> .2 <1, -0.7, -2> .3
  pigment { rgb <1, 0.3, 0.6> }
}
#macro Ball(C, R) sphere { C R pigment { rgb <1, 1, 0.3> } } #end
Ball(<0, 0.4, 0> .5)
Ball(<2.6, 0.4, -1> .4,)

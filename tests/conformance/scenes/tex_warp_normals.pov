// Conformance: mapping warps inside normals (a pattern sampled round the
// warped point, and the normal patterns bumps and ripples).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }
sphere { <-2.4, 1, 0>, 1 pigment { rgb 0.8 } normal { gradient x 0.8 scale 0.1 warp { spherical } translate <-2.4,1,0> } }
sphere { <0, 1, 0>, 1 pigment { rgb 0.8 } normal { bumps 0.8 scale 0.1 warp { cylindrical } translate <0,1,0> } }
sphere { <2.4, 1, 0>, 1 pigment { rgb 0.8 } normal { marble 0.8 scale 0.2 warp { toroidal major_radius 0.5 orientation x } translate <2.4,1,0> } }
plane { y, 0 pigment { rgb 0.7 } normal { ripples 0.7 scale 0.3 warp { planar z, 0.2 } } }

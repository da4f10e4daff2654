// Conformance: cylinder lights (parallel rays within a cylinder around the
// axis; radius and falloff are distances from it) casting parallel shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -7> look_at <0, 0, 0> angle 60 }
light_source { <-1, 6, -2> color rgb <1, 0.9, 0.7> cylinder point_at <-1, 0, 0> radius 1.5 falloff 3 tightness 0 }
light_source { <2, 5, 0> color rgb <0.4, 0.6, 1> cylinder point_at <2.5, 0, 0.5> radius 0.5 falloff 2 tightness 2 }
light_source { <0, 10, -10> color rgb 0.1 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.02 diffuse 0.9 } }
sphere { <-1, 1, -0.5>, 0.5 pigment { rgb 1 } }
box { <1.8, 0, -0.2>, <2.4, 1.5, 0.4> pigment { rgb <1, 1, 0.8> } }

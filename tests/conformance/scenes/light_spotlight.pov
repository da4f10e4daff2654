// Conformance: spotlights with different radius, falloff and tightness
// (povray 3.7: cos^tightness times a cubic edge from the falloff cone to
// the radius cone), and the defaults (radius 30, falloff 45, tightness 0).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 9, -6> look_at <0, 0, 0.5> angle 65 }
light_source { <-3, 5, 0> color rgb <1, 0.3, 0.3> spotlight point_at <-3, 0, 0> radius 10 falloff 25 tightness 0 }
light_source { <0, 5, 0> color rgb <0.3, 1, 0.3> spotlight point_at <0, 0, 0.5> radius 5 falloff 20 tightness 10 }
light_source { <3, 5, 0> color rgb <0.3, 0.3, 1> spotlight point_at <3.5, 0, 1> radius 15 falloff 18 tightness 50 }
light_source { <0, 4, 4> color rgb 0.8 spotlight point_at <0, 0, 3> }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.02 diffuse 0.9 } }
sphere { <0, 0.5, 0.5>, 0.5 pigment { rgb 1 } finish { ambient 0.02 } }
cylinder { <-3, 0, 0>, <-3, 1, 0>, 0.3 pigment { rgb 1 } }

// Conformance: area lights on a parallel light and on a cylinder light:
// the grid sits back along the axis from each lit point, as far as
// point_at is from the light's location.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> angle 55 }
light_source { <-1, 5, -1> color rgb <1, 0.9, 0.8> parallel point_at <0, 0, 0> area_light <4, 0, 0>, <0, 0, 4>, 5, 5 adaptive 1 }
light_source { <3, 4, 1> color rgb <0.3, 0.4, 0.6> cylinder point_at <2, 0, 0> radius 1.5 falloff 3 area_light <2, 0, 0>, <0, 0, 2>, 4, 4 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-0.5, 1, 0>, 1 pigment { rgb 1 } }
box { <1, 0, -1>, <1.6, 1.8, 0.4> pigment { rgb <1, 0.9, 0.7> } }

// Conformance: area lights without adaptive (every grid point traced):
// a 5x5 grid and a linear 8x1 light. Soft shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> angle 55 }
light_source { <-2, 6, -2> color rgb <1, 0.9, 0.8> area_light <3, 0, 0>, <0, 0, 3>, 5, 5 }
light_source { <3, 4, 1> color rgb <0.3, 0.4, 0.7> area_light <0, 0, 4>, <1, 0, 0>, 8, 1 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-0.5, 1, 0>, 1 pigment { rgb 1 } }
box { <1, 0, -1>, <1.6, 1.8, 0.4> pigment { rgb <1, 0.9, 0.7> } }

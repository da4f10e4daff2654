// Conformance: circular area lights (the grid squeezed into a disc), one
// with orient (the disc turned to face each lit point).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> angle 55 }
light_source { <-3, 5, -2> color rgb <1, 0.9, 0.8> area_light <3, 0, 0>, <0, 3, 0>, 5, 5 circular orient }
light_source { <3, 5, 1> color rgb <0.3, 0.4, 0.7> area_light <2, 0, 0>, <0, 0, 2>, 4, 4 circular adaptive 1 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-0.5, 1, 0>, 1 pigment { rgb 1 } }
box { <1, 0, -1>, <1.6, 1.8, 0.4> pigment { rgb <1, 0.9, 0.7> } }

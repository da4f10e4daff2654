// Conformance: at +Q4 povray traces shadows but does not sample area
// lights: an area light casts the hard shadow of a point light at its
// centre.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 55 }
light_source { <-3, 6, -3> color rgb <1, 0.9, 0.8> area_light <2, 0, 0>, <0, 0, 2>, 3, 3 }
light_source { <3, 5, -1> color rgb <0.3, 0.4, 0.7> area_light <0, 0, 2>, <0, 1, 0>, 5, 2 adaptive 1 circular }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-0.5, 1, 0>, 1 pigment { rgb <1, 0.8, 0.8> } finish { phong 0.6 specular 0.3 } }
box { <1, 0, -0.5>, <1.8, 1.4, 0.3> pigment { rgb <0.8, 1, 0.8> } }

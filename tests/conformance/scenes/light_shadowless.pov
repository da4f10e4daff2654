// Conformance: a shadowless light (lights everything, casts no shadow)
// beside an ordinary one, and an object with no_shadow. As in povray 3.7,
// a shadowless light gives no phong or specular highlights.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 55 }
light_source { <-4, 6, -3> color rgb <0.9, 0.5, 0.4> shadowless }
light_source { <4, 6, -2> color rgb <0.4, 0.6, 0.9> }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-1, 1, 0>, 1 pigment { rgb 1 } finish { phong 0.4 specular 0.3 } }
box { <0.8, 0, -0.5>, <1.8, 1.5, 0.5> pigment { rgb <0.8, 1, 0.8> } no_shadow }

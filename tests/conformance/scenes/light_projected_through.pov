// Conformance: projected_through: only light that crosses the object
// (which itself stays invisible) reaches the scene.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> angle 60 }
light_source { <0, 6, -1> color rgb <1, 0.9, 0.8> projected_through { box { <-1, 3, -1.5>, <0.5, 3.2, 0> } } }
light_source { <4, 5, -2> color rgb <0.2, 0.3, 0.6> projected_through { sphere { <3, 4, -1.5>, 0.4 } } }
light_source { <0, 10, -10> color rgb 0.15 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-0.5, 0.7, 0>, 0.7 pigment { rgb 1 } }

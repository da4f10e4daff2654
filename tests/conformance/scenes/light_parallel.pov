// Conformance: parallel lights (every ray parallel to point_at - location)
// with their shadows, beside a point light at the same place.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -8> look_at <0, 0.5, 0> angle 60 }
light_source { <-4, 6, -3> color rgb <1, 0.8, 0.6> parallel point_at <0, 0, 0> }
light_source { <3, 3, -1> color rgb <0.3, 0.4, 0.8> parallel point_at <2, 0, 1> }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-1, 1, 0>, 1 pigment { rgb 1 } finish { phong 0.6 } }
box { <1, 0, -0.5>, <2, 2, 0.5> pigment { rgb <0.8, 1, 0.8> } }

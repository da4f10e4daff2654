// Conformance: povray 3.7's rules for parallel lights measured against it:
// points behind the light's plane are still lit by a parallel light, but
// not by a parallel spotlight (which has no cone); parallel and cylinder
// lights fade with the distance from that plane, on either side of it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> angle 55 }
light_source { <0, 1, -1> color rgb <0.8, 0.6, 0.4> parallel point_at <0.5, 0, 0> fade_distance 2 fade_power 2 }
light_source { <1, 1.2, 1> color rgb <0.2, 0.4, 0.6> spotlight parallel point_at <0, 0, 1.5> radius 5 falloff 10 }
light_source { <-2, 4, 0> color rgb <0.3, 0.5, 0.2> cylinder point_at <-1.5, 0, 0> radius 1 falloff 2 fade_distance 3 fade_power 1 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-1, 1.5, 0>, 0.5 pigment { rgb 1 } }
sphere { <1, 0.5, 1>, 0.5 pigment { rgb 1 } }
box { <1, 0, -2>, <1.6, 1.8, -1.5> pigment { rgb <1, 0.9, 0.7> } }

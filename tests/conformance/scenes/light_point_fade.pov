// Conformance: point lights with distance fading (fade_distance,
// fade_power 1 and 2): light falls to 2 / (1 + (d / fade_distance)^power).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 60 }
light_source { <-3, 2, -1> color rgb <1.5, 0.9, 0.6> fade_distance 2 fade_power 1 }
light_source { <3, 2, 1> color rgb <0.5, 0.9, 1.6> fade_distance 1.5 fade_power 2 }
light_source { <0, 8, -6> color rgb 0.15 }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <0, 0.8, 0>, 0.8 pigment { rgb <1, 1, 1> } finish { ambient 0.05 diffuse 0.8 phong 0.5 } }
box { <-2.5, 0, 1.5>, <-1.5, 1.2, 2.5> pigment { rgb <0.9, 0.9, 0.6> } }

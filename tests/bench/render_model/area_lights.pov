// Area lights: two adaptive area lights over a few objects.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.6, 0> angle 50 }
light_source { <-6, 10, -6> rgb 0.8 area_light <3, 0, 0>, <0, 0, 3>, 9, 9 adaptive 1 circular orient }
light_source { <6, 8, -3> rgb 0.4 area_light <2, 0, 0>, <0, 0, 2>, 5, 5 adaptive 1 }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <-1.5, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.3> } finish { phong 0.5 } }
box { <0.3, 0, -0.8>, <2, 1.5, 0.8> rotate y * 25 pigment { rgb <0.3, 0.6, 0.9> } }
cylinder { <0, 0, 2>, <0, 2.5, 2>, 0.4 pigment { rgb <0.4, 0.9, 0.4> } }

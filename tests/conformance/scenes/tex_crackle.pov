// crackle: default form, solid cells, metric 1 with offset, form with
// three weights and metric 3 under turbulence, and as a normal.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,3,-6> look_at 0 angle 50 }
light_source { <-5,10,-10> color rgb 1 }
plane { y, -1 pigment { crackle color_map { [0 rgb 0] [0.05 rgb <1,0.8,0.2>] [1 rgb <0.2,0.3,1>] } scale 0.5 } }
sphere { <-1.5,0.2,0>, 1 pigment { crackle solid color_map { [0 rgb <1,0,0>] [1 rgb <0,1,0>] } scale 0.3 } }
sphere { <0.8,0.2,0>, 1 pigment { crackle form <1,0,0> metric 1 offset 0.1 color_map { [0 rgb 1] [1 rgb <0,0,0.5>] } scale 0.4 }
  normal { crackle 0.6 scale 0.3 } }
box { <2,-1,1>, <3,1,2> pigment { crackle form <0.3,0.5,0.7> metric 3 turbulence 0.3 color_map { [0 rgb <1,1,0>] [1 rgb <0.5,0,0.5>] } scale 0.4 } }

// pigment_pattern (as a pigment's pattern, a normal and in a texture) and
// the object pattern (pigment list with defaults and with colours, normal
// list, texture list, transformed). The quilted normal is moved off the
// disc's plane: on a cube face povray's rounding of the hit point picks
// either cube at random (grain that cannot be reproduced).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,3,-7> look_at <0,0.3,0> angle 55 }
light_source { <-5,10,-10> color rgb 1 }
#declare Star = union { sphere { <0.5,0,0.5>, 0.45 } box { <-0.2,-0.2,-0.2>, <0.2,0.2,0.2> } }
plane { y, -1 pigment { object { Star rgb <0.2,0.3,0.6>, rgb <1,0.6,0.1> } scale 1.5 translate <0.5,-1,0> } }
sphere { <-2.2,0.2,0>, 1 pigment { pigment_pattern { gradient y color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] } scale 0.3 }
  color_map { [0 rgb <0,0.2,0>] [0.3 rgb <1,1,0>] [0.6 rgb <0.2,0,0.4>] } } }
sphere { <0,0.2,0>, 1 pigment { object { sphere { <0.3,0.3,-0.5>, 0.6 } } }
  normal { pigment_pattern { bozo color_map { [0 rgb 0] [1 rgb 1] } scale 0.2 } 0.8 } }
box { <1.3,-0.8,-0.5>, <3.1,1.2,0.5> texture { object { cylinder { <2.2,-2,-1>, <2.2,2,-1>, 0.7 }
  texture { pigment { rgb <0.8,0.8,0.8> } normal { bumps 0.5 scale 0.1 } },
  texture { pigment { rgb <0.9,0.2,0.2> } finish { phong 0.8 } } } } }
disc { <0,0,0>, <0,0,-1>, 0.9 pigment { rgb <0.9,0.9,0.9> } normal { object { box { <-0.3,-2,-2>, <0.3,2,2> } normal { bumps 0.8 scale 0.05 }, normal { quilted 0.5 scale 0.2 translate z*0.05 } } } translate <-1,1.8,1> }
disc { <0,0,0>, <0,0,-1>, 0.9 texture { pigment_pattern { radial frequency 6 color_map { [0 rgb 0] [1 rgb 1] } }
  texture_map { [0.3 pigment { rgb <0,0.5,0> }] [0.7 pigment { rgb <1,1,0.6> }] } rotate x*90 } translate <1.2,1.8,1> }

// cells, quilted (default and with controls), spiral1 and spiral2 pigments,
// and quilted and spiral1 as normals.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,3,-7> look_at <0,0.3,0> angle 55 }
light_source { <-5,10,-10> color rgb 1 }
plane { y, -1 pigment { cells color_map { [0 rgb <0.1,0.1,0.4>] [1 rgb <1,0.9,0.6>] } scale 0.7 } }
sphere { <-2.2,0.2,0>, 1 pigment { quilted color_map { [0 rgb <0.8,0,0>] [0.5 rgb 1] [1 rgb <0,0,0.8>] } scale 0.4 } }
sphere { <0,0.2,0>, 1 pigment { quilted control0 0.2 control1 0.9 color_map { [0 rgb 0] [1 rgb <1,1,0>] } scale 0.5 }
  normal { quilted 0.8 scale 0.3 } }
box { <1.3,-0.8,-0.5>, <3.1,1.2,0.5> pigment { spiral1 3 color_map { [0 rgb <0,0.5,0>] [1 rgb <1,1,1>] } scale 0.6 translate <2.2,0.2,0> } }
disc { <0,0,0>, <0,0,-1>, 0.9 pigment { spiral2 5 color_map { [0 rgb <1,0.5,0>] [1 rgb <0,0,0.5>] } scale 0.8 } translate <-1,1.8,1> }
disc { <0,0,0>, <0,0,-1>, 0.9 pigment { rgb <0.9,0.9,0.9> } normal { spiral1 2 0.6 scale 0.5 } translate <1.2,1.8,1> }

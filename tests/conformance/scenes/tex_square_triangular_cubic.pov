// The 3.7 block patterns square (4 colours), triangular and cubic (6
// colours each): default colours, colour lists, transformed,
// as normals and textures.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,3,-7> look_at <0,0.3,0> angle 55 }
light_source { <-5,10,-10> color rgb 1 }
plane { y, -1.001 pigment { square scale 0.7 } }
sphere { <-2.2,0.2,0>, 1 pigment { triangular rgb <0.9,0.2,0.2>, rgb <0.2,0.9,0.2>, rgb <0.2,0.2,0.9>,
  rgb 1, rgb 0.5, rgb <1,1,0> scale 0.4 rotate x*-60 } }
sphere { <0,0.2,0>, 1 pigment { cubic translate <0.2,0.1,0> rotate <20,30,0> translate <0,0.2,0> } }
box { <1.3,-0.8,-0.5>, <3.1,1.2,0.5> texture { square texture { pigment { rgb <1,0.8,0.6> } },
  texture { pigment { rgb <0.3,0.3,0.8> } finish { phong 0.7 } }, texture { pigment { rgb 0.8 } normal { bumps 0.6 scale 0.1 } },
  texture { pigment { rgb <0.1,0.6,0.2> } } scale 0.35 rotate x*-90 } }
disc { <0,0,0>, <0,0,-1>, 0.9 pigment { rgb 0.9 } normal { triangular normal { bumps 0.8 scale 0.05 }, normal { quilted 0.6 scale 0.15 translate 0.05 },
  normal { dents 0.5 scale 0.1 }, normal { bumps 0.2 scale 0.2 }, normal { wrinkles 0.5 scale 0.2 }, normal { ripples 0.5 scale 0.3 } scale 0.5 rotate x*-90 } translate <-1,1.8,1> }
disc { <0,0,0>, <0,0,-1>, 0.9 pigment { cubic rgb 0, rgb 0.2, rgb 0.4, rgb 0.6, rgb 0.8, rgb 1 rotate <30,40,50> } translate <1.2,1.8,1> }

// Below +Q6 povray 3.7 computes no pigment pattern that has a quick_color:
// the surface takes that colour and is shaded as usual; patterns without
// one are still computed (measured at +Q3 and +Q5).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,2,-5> look_at 0 }
light_source { <-5,10,-5> rgb 1 }
plane { y, -1 pigment { checker rgb 1 rgb <0.2,0.3,0.8> } }
sphere { 0, 1 pigment { marble turbulence 0.5 color_map { [0 rgb <1,0,0>] [1 rgb <1,1,0>] } } finish { phong 0.5 } }
sphere { <2,0,1>, 1 pigment { granite quick_color rgb <0,1,0> } }

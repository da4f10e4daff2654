// density_file df3 as a pigment pattern with interpolate 0, 1 and 2 and
// as a normal (density_blob.df3 from image_make_files.py). The boxes stay
// inside the unit cube: on its faces povray rounds points to either side.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,2,-6> look_at <0,0.3,0> angle 55 }
light_source { <-5,10,-10> color rgb 1 }
#declare CM = color_map { [0 rgb <0,0,0.3>] [0.4 rgb <0.2,0.6,1>] [0.7 rgb <1,1,0.3>] [1 rgb <1,0.2,0>] }
box { 0.01, 0.99 pigment { density_file df3 "density_blob.df3" color_map { CM } } scale 1.6 translate <-3,-0.8,0> }
box { 0.01, 0.99 pigment { density_file df3 "density_blob.df3" interpolate 1 color_map { CM } } scale 1.6 translate <-0.8,-0.8,0> rotate y*10 }
box { 0.01, 0.99 pigment { density_file df3 "density_blob.df3" interpolate 2 color_map { CM } } scale 1.6 translate <1.4,-0.8,0> }
plane { y, -0.8 pigment { rgb 0.8 } normal { density_file df3 "density_blob.df3" interpolate 1 bump_size 0.5 scale 2 translate <-1,-1,-2.5> } }

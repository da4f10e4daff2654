// mandel and julia (exponent 3, exterior type 0) pigments.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <-0.5,0,-3> look_at <-0.5,0,0> angle 60 }
light_source { <-5,10,-10> color rgb 1 }
plane { z, 0 pigment { mandel 60 color_map { [0 rgb <0,0,0.3>] [0.1 rgb <0,0.5,1>] [0.3 rgb <1,1,0>] [1 rgb 0] } } finish { ambient 1 diffuse 0 } }
plane { z, -0.5 clipped_by { box { <0.3,0.2,-1>, <1.6,1.4,1> } } pigment { julia <0.353, 0.288>, 40 exponent 3 exterior 0, 0.4 color_map { [0 rgb 1] [0.5 rgb <1,0,0>] [1 rgb <0,0.4,0>] } scale 0.5 translate <1,0.8,0> } finish { ambient 1 diffuse 0 } }

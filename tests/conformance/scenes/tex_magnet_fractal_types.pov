// magnet 1 and 2 (mandel and julia forms) and the interior and exterior
// colouring types of the fractal patterns.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0,0,-5> look_at 0 right x*8 up y*6 }
#declare M = finish { ambient 1 diffuse 0 }
#declare CM = color_map { [0 rgb <0,0,0.3>] [0.2 rgb <0,0.6,1>] [0.5 rgb <1,1,0.2>] [0.8 rgb <1,0.3,0>] [1 rgb 0] }
box { <-4,0,0>, <-1.34,3,1> pigment { magnet 1 mandel 40 color_map { CM } scale 0.6 translate <-2.2,1.5,0> } finish { M } }
box { <-1.33,0,0>, <1.33,3,1> pigment { magnet 2 mandel 30 interior 1, 1 color_map { CM } scale 0.5 translate <0.2,1.5,0> } finish { M } }
box { <1.34,0,0>, <4,3,1> pigment { magnet 1 julia <0.2,0.6>, 30 interior 3, 2 exterior 6, 0.3 color_map { CM } scale 0.8 translate <2.6,1.5,0> } finish { M } }
box { <-4,-3,0>, <-1.34,0,1> pigment { mandel 40 interior 2, 1 exterior 3, 0.2 color_map { CM } scale 0.9 translate <-2.4,-1.5,0> } finish { M } }
box { <-1.33,-3,0>, <1.33,0,1> pigment { julia <-0.75,0.11>, 50 interior 6, 0.8 exterior 4, 0.05 color_map { CM } scale 1.1 translate <0,-1.5,0> } finish { M } }
box { <1.34,-3,0>, <4,0,1> pigment { magnet 2 julia <0.6,0.9>, 30 interior 1, 2 color_map { CM } scale 0.7 translate <2.6,-1.5,0> } finish { M } }

// slope (short form, ranges, altitude with weights) and aoi: pigments on
// transformed objects (povray uses the world-space normal), aoi after a
// bumps normal (the perturbed normal), slope as a texture_map pattern and
// in a pigment_map.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,2,-6> look_at <0,0.3,0> angle 55 }
light_source { <-5,10,-10> color rgb 1 }
#declare CM = color_map { [0 rgb <0,0,0.4>] [0.5 rgb <0.3,0.8,0.3>] [1 rgb <1,1,0.8>] }
sphere { 0, 1 pigment { slope { y altitude y*2, -1, 1 } color_map { CM } rotate z*30 } scale <1,0.6,1> translate <-2,0.3,0> }
sphere { <0,0.3,0>, 1 pigment { aoi color_map { CM } } normal { bumps 0.8 scale 0.2 } }
sphere { <2,0.3,0>, 1 texture { slope { y, 0.4, 0.8 } texture_map { [0 pigment { rgb <0.5,0.3,0.1> }] [1 pigment { rgb 1 } finish { phong 0.5 }] } } }
box { <-3,-0.7,-1.5>, <3,-0.5,-1.2> pigment { slope z pigment_map { [0 rgb 0] [1 aoi color_map { CM }] } scale 2 } }
sphere { <-1,2,1.5>, 0.7 pigment { slope { <1,2,0>, 0.3, 0.9 altitude <0,1,1>, 1, 3 } color_map { CM } translate y*0.5 } }
plane { y, -0.7 pigment { slope { y*0.5 altitude y, -1, 0 } color_map { CM } } normal { bumps 0.3 scale 0.3 } }

// The facets normal: size mode on spheres (default size, size with
// metric 1 and transformations), coords mode on a plane, a box and a
// sphere (metric 3, transformed). Surfaces avoid cell boundaries: povray
// rounds hit points on them to either side.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,3,-7> look_at <0,0.3,0> angle 55 }
light_source { <-5,10,-10> color rgb 1 }
light_source { <6,4,-3> color rgb <0.3,0.3,0.4> }
plane { y, -1.03 pigment { rgb <0.6,0.7,0.9> } normal { facets coords 0.4 size 0.3 } }
sphere { <-2.2,0.2,0>, 1 pigment { rgb <1,0.8,0.3> } normal { facets } }
sphere { <0,0.2,0>, 1 pigment { rgb <0.9,0.9,0.9> } finish { phong 0.6 } normal { facets size 0.25 metric 1 scale <1,1.5,1> rotate 20*z } }
box { <1.31,-0.83,-0.47>, <3.07,1.17,0.53> pigment { rgb <0.4,0.9,0.4> } normal { facets coords 0.8 size 0.2 metric 3 rotate <10,20,30> } }
sphere { <-1,2,1.5>, 0.7 pigment { rgb <0.9,0.4,0.4> } normal { facets coords 0.5 size 0.15 } }
sphere { <1.2,2,1.5>, 0.7 pigment { rgb <0.5,0.5,1> } normal { facets size 0.5 translate 0.3 } }

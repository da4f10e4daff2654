// Anti-aliasing conformance: sharp geometric edges against the background
// and between objects (no pattern edges, whose sub-pixel positions are
// numerically chaotic). The options are in manifest.txt.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.137,1.071,-5.29> look_at <0.011,0.513,0.07> }
light_source { <5,8,-6> rgb 1 }
background { rgb <0.3,0.4,0.6> }
sphere { <-0.8,0.6,0>, 0.8 pigment { rgb <1,0.3,0.2> } finish { phong 0.8 } }
box { <0.2,0,-0.5>, <1.6,1.4,0.5> rotate y*30 pigment { rgb <0.2,0.5,1> } }
box { <-3,-0.1,-2>, <3,0,3> pigment { rgb <0.6,0.6,0.5> } }
cylinder { <-2,0,1>, <2,2.5,2>, 0.05 pigment { rgb <1,1,0> } }

// Conformance: checker and brick on faces lying exactly on cell boundaries.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.3, 3.3, -7> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { checker rgb <0.2, 0.2, 0.6>, rgb <0.9, 0.9, 0.7> } }
box { <-3, 0, -1>, <-1, 2, 1> pigment { checker rgb 1, rgb <1, 0, 0> scale 0.5 } }
box { <1, 0, -1>, <3, 3, 1> pigment { brick rgb 0.8, rgb <0.6, 0.2, 0.1> scale 0.125 } }

// Conformance: perspective camera with an explicit horizontal field of view
// (angle) and an explicit right vector of exactly 4/3 (the default is
// <1.33,0,0>, very slightly different).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <3, 2.5, -5>
    right x * 4 / 3
    up y
    angle 48
    look_at <0, 0.7, 0>
}

light_source { <2, 9, -9> color rgb <1, 1, 1> }

plane { y, 0 pigment { color rgb <0.8, 0.75, 0.65> } }

sphere { <0, 1, 0>, 1 pigment { color rgb <0.25, 0.6, 0.85> } finish { phong 0.5 } }

box { <-2.6, 0, -0.6>, <-1.5, 0.7, 0.8> pigment { color rgb <0.9, 0.3, 0.3> } }

box { <1.1, 0, 1>, <1.8, 2, 1.7> pigment { color rgb <0.95, 0.8, 0.3> } }

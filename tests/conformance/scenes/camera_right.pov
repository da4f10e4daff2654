// Conformance: a 2:1 image (rendered at 320x160) with right x*2 so pixels
// stay square; angle sets the horizontal field of view relative to the
// length of right.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 1.6, -7>
    up y
    right x * 2
    angle 70
    look_at <0, 1, 0>
}

light_source { <-3, 7, -8> color rgb <1, 1, 1> }

plane { y, 0 pigment { color rgb <0.7, 0.7, 0.7> } }

sphere { <-3, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.25> } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.3, 0.85, 0.35> } }
sphere { <3, 1, 0>, 1 pigment { color rgb <0.3, 0.4, 0.95> } }

box { <-6, 0, 2>, <6, 3, 2.5> pigment { color rgb <0.85, 0.85, 0.8> } }

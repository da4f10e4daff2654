// Conformance: a rolled camera. sky tilts the image's "up" direction;
// look_at then rebuilds right and up around the new sky vector.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <-2, 3, -6>
    sky <0.45, 1, 0>
    angle 55
    look_at <0, 0.8, 0>
}

light_source { <4, 10, -5> color rgb <1, 1, 1> }

plane { y, 0 pigment { color rgb <0.65, 0.7, 0.8> } }

box { <-1, 0, -1>, <1, 0.5, 1> pigment { color rgb <0.9, 0.6, 0.3> } }

sphere { <0, 1.3, 0>, 0.8 pigment { color rgb <0.85, 0.85, 0.9> } finish { phong 0.7 phong_size 25 } }

box { <2, 0, 1>, <2.6, 2.5, 1.6> pigment { color rgb <0.4, 0.3, 0.8> } }

// Conformance: one of each primitive (sphere, box, plane) under a single
// white point light, default finish, camera with location/look_at only
// (so the default right vector <1.33,0,0> and angle-less direction apply).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 2.2, -6>
    look_at <0, 0.8, 0>
}

light_source { <-5, 8, -6> color rgb <1, 1, 1> }

plane { y, 0 pigment { color rgb <0.75, 0.75, 0.7> } }

sphere { <-1.3, 1, 0>, 1 pigment { color rgb <0.9, 0.25, 0.15> } }

box { <0.4, 0, -0.6>, <2.2, 1.5, 0.9> pigment { color rgb <0.2, 0.45, 0.9> } }

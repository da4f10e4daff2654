// Conformance: a camera given entirely by explicit vectors and no look_at.
// direction replaces angle (its length sets the zoom), and up/right are a
// perpendicular pair rotated about 16 degrees about the view axis (a 7-24-25
// triangle keeps them exactly unit length), so the image is tilted.
// #declare arithmetic builds the vectors.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare S = 7 / 25;
#declare C = 24 / 25;
#declare UpVec = <S, C, 0>;
#declare RightVec = <C, -S, 0> * 4 / 3;

camera {
    location <0, 1.5, -6>
    direction <0, 0, 1.6>
    right RightVec
    up UpVec
}

light_source { <-5, 8, -7> color rgb <1, 1, 1> }

plane { y, 0 pigment { color rgb <0.75, 0.7, 0.7> } }

sphere { <-1.4, 1, 0>, 1 pigment { color rgb <0.2, 0.75, 0.7> } }

box { <0.3, 0, -0.5>, <2.1, 1.8, 1> pigment { color rgb <0.85, 0.4, 0.6> } }

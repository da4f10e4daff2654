// Conformance: inverse — intersection with an inverse sphere (a
// difference written another way), a difference whose subtrahend is
// itself inverse (so it acts as an intersection), an inverse CSG inside a
// difference, and a top-level inverse sphere (looks the same as a plain
// one).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -8> look_at <0, 0.3, 0> angle 55 }

light_source { <-5, 10, -8> color rgb <1, 1, 1> }
light_source { <6, 4, -5> color rgb <0.3, 0.3, 0.3> }

plane { y, -1 pigment { color rgb <0.7, 0.7, 0.7> } }

intersection { box { -0.8, 0.8 } sphere { <0.8, 0.8, -0.8>, 0.9 inverse }
    rotate y * 20 translate <-2.5, 0, 0.8> pigment { color rgb <0.9, 0.4, 0.2> } }

difference { box { -0.8, 0.8 } sphere { 0, 1 inverse }
    translate <0, 0, 0.8> pigment { color rgb <0.3, 0.8, 0.4> } }

difference { sphere { 0, 0.9 } intersection { box { -0.6, 2 } sphere { 0, 1.1 } inverse }
    translate <2.5, 0, 0.8> pigment { color rgb <0.3, 0.4, 0.95> } }

sphere { 0, 0.7 inverse translate <-1.2, -0.3, -1.8> pigment { color rgb <0.9, 0.8, 0.3> } }

intersection { cylinder { <0, -1, 0>, <0, 1, 0>, 0.7 } cylinder { <0, -2, 0>, <0, 2, 0>, 0.4 inverse } plane { y, 0.2 }
    translate <1.3, 0, -1.8> pigment { color rgb <0.8, 0.4, 0.9> } }

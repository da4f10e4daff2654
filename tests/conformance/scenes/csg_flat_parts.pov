// Conformance: discs and triangles inside CSG, povray's way — a
// triangle has no inside (difference { sphere triangle } keeps only the
// triangle's part inside the sphere), a disc's inside is the half-space
// behind it (difference { sphere disc } is a hemisphere), and an
// intersection with a disc is only seen along rays through the common
// part of the operands' bounding boxes, the disc's being a thin slab.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -6> look_at 0 angle 60 }

light_source { <5, 10, -10> color rgb 1 }

intersection { sphere { 0, 1 } disc { 0, y, 2 } translate <-2.5, 1.5, 0> pigment { rgb <1, 0.2, 0.2> } }
intersection { box { -1, 1 } disc { 0, y, 2 } translate <0, 1.5, 0> pigment { rgb <0.2, 0.9, 0.3> } }
intersection { sphere { 0, 1 } triangle { <-2, 0, -2>, <2, 0, -2>, <0, 0, 2> } translate <2.5, 1.5, 0> pigment { rgb <0.3, 0.4, 1> } }
difference { sphere { 0, 1 } disc { 0, y, 0.5 } translate <-2.5, -1.5, 0> pigment { rgb <1, 0.8, 0.2> } }
difference { sphere { 0, 1 } disc { 0, -y, 2 } translate <0, -1.5, 0> pigment { rgb <0.8, 0.3, 0.9> } }
difference { sphere { 0, 1 } triangle { <-2, 0, -2>, <2, 0, -2>, <0, 0, 2> } translate <2.5, -1.5, 0> pigment { rgb <0.2, 0.8, 0.8> } }

// Conformance: CSG with coincident faces, where povray's inside tests
// decide: a box minus a box whose top is flush with it (povray keeps a lid
// over the pit), a box minus a box sharing three faces with it, two boxes
// touching face to face intersected (the shared face remains), two
// adjacent boxes merged, and a cylinder minus a cylinder flush with its top.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 6, -7> look_at <0, 0, 0> angle 55 }

light_source { <-4, 10, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -6> color rgb <0.3, 0.3, 0.3> }

plane { y, -1.01 pigment { color rgb <0.7, 0.7, 0.7> } }

difference { box { -1, 1 } box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> }
    pigment { color rgb <0.3, 0.85, 0.3> } scale 0.8 translate <-2.5, -0.2, 1> }

difference { box { -1, 1 } box { <0, -1, -1>, <2, 1, 1> }
    pigment { color rgb <0.9, 0.3, 0.3> } scale 0.8 translate <0, -0.2, 1> }

intersection { box { <-1, -1, -1>, <1, 0, 1> } box { <-1, 0, -1>, <1, 1, 1> }
    pigment { color rgb <0.3, 0.4, 0.95> } scale 0.8 translate <2.5, 0, 1> }

merge { box { <-1, -1, -0.5>, <0, 0, 0.5> } box { <0, -1, -0.5>, <1, 0, 0.5> }
    pigment { color rgb <0.9, 0.8, 0.3> } translate <-1.5, 0, -1.8> }

// Cylinders: the pit's cap is flush with the top; the cylinders' inside
// tests leave out their surface, so the outer cap stays whole.
difference { cylinder { <0, -1, 0>, <0, 0, 0>, 0.8 } cylinder { <0, -0.5, 0>, <0, 0, 0>, 0.4 }
    pigment { color rgb <0.8, 0.4, 0.9> } translate <1.8, 0, -1.8> }

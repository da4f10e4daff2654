// Conformance: surfaces of revolution, capped and open (seen from above
// so the open top shows the inside).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.4, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
#declare Pts = array[7] { <0.3, -1.4>, <0.6, -1>, <0.9, -0.5>, <0.4, 0.2>, <0.5, 0.8>, <0.9, 1.2>, <1, 1.5> }
sor {
    7, Pts[0], Pts[1], Pts[2], Pts[3], Pts[4], Pts[5], Pts[6]
    pigment { color rgb <0.9, 0.3, 0.2> }
    translate <-1.6, 0, 0>
}
sor {
    7, Pts[0], Pts[1], Pts[2], Pts[3], Pts[4], Pts[5], Pts[6]
    open
    pigment { color rgb <0.3, 0.4, 0.9> }
    translate <1.6, 0, 0>
}

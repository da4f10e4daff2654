// Conformance: union and merge. Clipping opens them up: the clipped union
// shows the inner surfaces of its overlapping spheres, the clipped merge
// only the outer skin. A union of a box and cylinder with their own
// pigments, and a merge whose children take the merge's pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -8> look_at <0, 0.5, 0> angle 55 }

light_source { <-4, 10, -8> color rgb <1, 1, 1> }
light_source { <6, 5, -2> color rgb <0.3, 0.3, 0.3> }

plane { y, -1 pigment { color rgb <0.7, 0.7, 0.7> } }

#declare Pair = union { sphere { <-0.5, 0, 0>, 0.9 } sphere { <0.5, 0, 0>, 0.9 } }

union { sphere { <-0.5, 0, 0>, 0.9 } sphere { <0.5, 0, 0>, 0.9 }
    clipped_by { plane { z, 0 } }
    pigment { color rgb <0.9, 0.4, 0.2> }
    rotate y * -40 translate <-2.4, 0, 0.5> }

merge { sphere { <-0.5, 0, 0>, 0.9 } sphere { <0.5, 0, 0>, 0.9 }
    clipped_by { plane { z, 0 } }
    pigment { color rgb <0.2, 0.6, 0.9> }
    rotate y * -40 translate <1.4, 0, 0.5> }

union {
    box { <-0.6, -1, -0.6>, <0.6, 0.2, 0.6> pigment { color rgb <0.9, 0.9, 0.3> } }
    cylinder { <0, -1, 0>, <0, 1, 0>, 0.3 pigment { color rgb <0.6, 0.3, 0.8> } }
    translate <-0.6, 0, -2.2>
}

merge {
    object { Pair scale 0.6 }
    cylinder { <0, -1, 0>, <0, 0, 0>, 0.25 }
    pigment { color rgb <0.3, 0.85, 0.4> }
    finish { phong 0.5 }
    translate <2.2, 0, -2.4>
}

// Conformance: blobs and tori in CSG (which needs every crossing and the
// inside test): a blob minus a box, the intersection of a blob and a
// sphere, a torus merged with a blob, and a clipped blob.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -7> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }

#declare Pair = blob {
    threshold 0.5
    sphere { <-0.5, 0, 0>, 1, 1 }
    sphere { <0.5, 0, 0>, 1, 1 }
    cylinder { <0, -0.7, 0>, <0, 0.7, 0>, 0.5, 1 }
}
difference {
    object { Pair }
    box { <-2, 0.1, -2>, <2, 2, 0> }
    translate <-2, 0, 0.5>
    pigment { color rgb <0.9, 0.5, 0.2> } finish { phong 0.5 }
}
intersection {
    object { Pair }
    sphere { <0.3, 0, -0.2>, 0.75 }
    translate <0, 0.2, 1.5>
    pigment { color rgb <0.3, 0.8, 0.35> } finish { phong 0.4 }
}
merge {
    torus { 0.9, 0.25 rotate x * 90 }
    object { Pair scale 0.6 }
    translate <2, 0.2, 0.2>
    pigment { color rgb <0.3, 0.5, 0.95> } finish { phong 0.3 }
}
object { Pair clipped_by { plane { z, 0 } } inverse rotate y * 50 translate <0.2, -0.2, -1.8>
    pigment { color rgb <0.9, 0.85, 0.3> } }

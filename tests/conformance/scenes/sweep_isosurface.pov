// Conformance: isosurfaces of user functions in box containers: a rounded
// blobby shape cut by its container (closed), a wavy open surface, and a
// torus given by its implicit function.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
#declare Torus = function(x, y, z, R, r) { pow(sqrt(x*x + z*z) - R, 2) + y*y - r*r }
isosurface {
    function { x*x + y*y + z*z - 1 + 0.3*sin(4*x)*sin(4*y) }
    contained_by { box { <-1.2, -1.2, -1.2>, <1.2, 0.6, 1.2> } }
    max_gradient 4
    pigment { color rgb <0.9, 0.3, 0.2> }
    translate <-2.2, 0.2, 0>
}
isosurface {
    function { y - 0.25*sin(3*x)*cos(3*z) }
    contained_by { box { <-1, -1, -1>, <1, 1, 1> } }
    open
    max_gradient 1.5
    pigment { color rgb <0.2, 0.7, 0.3> }
    translate <0.2, 0, 1>
}
isosurface {
    function { Torus(x, y, z, 0.8, 0.3) }
    contained_by { box { -1.2, 1.2 } }
    threshold 0
    accuracy 0.0005
    max_gradient 2.6
    pigment { color rgb <0.3, 0.4, 0.9> }
    rotate <-60, 0, 0>
    translate <2.3, 0.3, 0>
}

// Conformance: isosurfaces in sphere containers: a noisy-looking sum of
// cosines cut by its sphere (the sphere closes it), the same open, and a
// threshold other than zero.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
#declare F = function { cos(3*x) + cos(3*y) + cos(3*z) }
isosurface {
    function { F(x, y, z) }
    contained_by { sphere { 0, 1.1 } }
    max_gradient 5.2
    pigment { color rgb <0.9, 0.3, 0.2> }
    translate <-2.2, 0.2, 0>
}
isosurface {
    function { F(x, y, z) }
    contained_by { sphere { 0, 1.1 } }
    open
    max_gradient 5.2
    pigment { color rgb <0.2, 0.7, 0.3> }
    translate <0.2, 0.2, 1>
}
isosurface {
    function { sqrt(x*x + y*y*2 + z*z) }
    threshold 0.8
    contained_by { sphere { <0, 0, 0>, 1 } }
    max_gradient 1.5
    pigment { color rgb <0.3, 0.4, 0.9> }
    translate <2.3, 0.3, 0>
}

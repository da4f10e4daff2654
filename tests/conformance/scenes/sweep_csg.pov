// Conformance: the swept and numerical shapes in CSG, which uses their
// every crossing and inside tests: a superellipsoid minus a prism, a lathe
// intersected with a box, a sphere_sweep merged with a sor, and an
// isosurface (all_intersections) minus a sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.3, 0> angle 55 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
difference {
    superellipsoid { <0.4, 0.4> }
    prism { -2, 2, 5, <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <-0.5, -0.5> rotate <-90, 0, 0> }
    pigment { color rgb <0.9, 0.3, 0.2> }
    rotate <0, 30, 0>
    translate <-2.6, 0, 0>
}
intersection {
    lathe { bezier_spline 8, <0, -1>, <0.7, -1>, <1, -0.5>, <1, 0>, <1, 0>, <1, 0.6>, <0.6, 1>, <0, 1> }
    box { <-2, -2, -2>, <2, 0.4, 0.3> }
    pigment { color rgb <0.2, 0.7, 0.3> }
    translate <-0.4, 0, 0.8>
}
merge {
    sphere_sweep { linear_spline 3, <-0.8, -0.8, 0>, 0.25, <0, 0.6, 0>, 0.35, <0.8, -0.8, 0>, 0.25 }
    sor { 5, <0.2, -1.2>, <0.5, -0.9>, <0.6, -0.2>, <0.3, 0.4>, <0.2, 0.8> }
    pigment { color rgb <0.3, 0.4, 0.9> filter 0.4 }
    translate <1.5, 0, -0.6>
}
difference {
    isosurface {
        function { x*x + y*y + z*z - 0.64 + 0.1 * sin(6 * x) }
        contained_by { box { -1, 1 } }
        max_gradient 3
        all_intersections
    }
    sphere { <0, 0.4, -0.5>, 0.5 }
    pigment { color rgb <0.9, 0.8, 0.2> }
    translate <3.2, 0, 1>
}

// Conformance: conic_sweep prisms (the outline scaled by the height):
// a capped frustum of a hexagon and an open quadratic_spline one.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
prism {
    conic_sweep linear_spline
    0.3, 1, 7,
    <1, 0>, <0.5, 0.866>, <-0.5, 0.866>, <-1, 0>, <-0.5, -0.866>, <0.5, -0.866>, <1, 0>
    pigment { color rgb <0.2, 0.7, 0.3> }
    rotate <180, 0, 0>
    translate <-1.6, 1, 0>
    scale 1.5
}
prism {
    conic_sweep quadratic_spline
    0.2, 1, 6,
    <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>
    open
    pigment { color rgb <0.9, 0.8, 0.2> }
    rotate <180, 0, 0>
    scale <1, 2, 1>
    translate <1.6, 1, 0>
}

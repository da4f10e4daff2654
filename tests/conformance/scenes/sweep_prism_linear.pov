// Conformance: linear_spline prisms: a star, and a square with a square
// hole (two sub-shapes), tilted.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
prism {
    linear_sweep linear_spline
    -1, 0.5, 11,
    <0, 1.2>, <0.3, 0.4>, <1.1, 0.4>, <0.5, -0.1>, <0.7, -0.9>, <0, -0.4>, <-0.7, -0.9>, <-0.5, -0.1>,
    <-1.1, 0.4>, <-0.3, 0.4>, <0, 1.2>
    pigment { color rgb <0.9, 0.3, 0.2> }
    translate <-1.7, 0, 0>
}
prism {
    linear_spline
    0, 1, 10,
    <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>,
    <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <-0.5, -0.5>
    pigment { color rgb <0.3, 0.4, 0.9> }
    rotate <-20, 30, 0>
    translate <1.6, -0.5, 0.5>
}

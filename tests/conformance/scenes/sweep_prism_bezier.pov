// Conformance: bezier_spline and cubic_spline prisms: a rounded blob
// outline and a cubic closed curve.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
prism {
    bezier_spline
    -1, 0.3, 16,
    <0, -1>, <0.8, -1>, <1.2, -0.4>, <1, 0>,
    <1, 0>, <0.8, 0.6>, <0.4, 1.2>, <0, 0.7>,
    <0, 0.7>, <-0.4, 1.2>, <-0.8, 0.6>, <-1, 0>,
    <-1, 0>, <-1.2, -0.4>, <-0.8, -1>, <0, -1>
    pigment { color rgb <0.8, 0.4, 0.8> }
    translate <-1.6, 0, 0>
}
prism {
    cubic_spline
    -1, 0.6, 8,
    <-0.8, -0.6>, <0, -1>, <0.9, -0.3>, <0.5, 0.8>, <-0.6, 0.5>, <-0.8, -0.6>, <0, -1>, <0.9, -0.3>
    pigment { color rgb <0.3, 0.7, 0.8> }
    rotate <0, 20, 0>
    translate <1.5, 0, 0.3>
}

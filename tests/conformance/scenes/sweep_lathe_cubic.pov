// Conformance: quadratic_spline and cubic_spline lathes (the first and
// the outer points set the slopes).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
lathe {
    cubic_spline 8,
    <0.3, -1.5>, <0, -1>, <0.9, -0.7>, <0.4, 0>, <0.7, 0.8>, <0.2, 1.2>, <0, 1.4>, <-0.3, 1.6>
    pigment { color rgb <0.2, 0.7, 0.3> }
    translate <-1.6, 0, 0>
}
lathe {
    quadratic_spline 7,
    <0, -1.5>, <0, -1>, <1, -0.5>, <0.5, 0.3>, <0.8, 0.9>, <0.3, 1.3>, <0, 1.4>
    pigment { color rgb <0.9, 0.8, 0.2> }
    translate <1.4, 0, 0.3>
}

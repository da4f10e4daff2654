// Conformance: a b_spline sphere sweep (smooth, not through its points)
// with a varying radius.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
sphere_sweep {
    b_spline 7,
    <-3.5, 0, 0>, 0.2, <-3, 0, 0>, 0.2, <-2, 2, 1>, 0.4, <0, -1, 0>, 0.6, <1, 2, 1>, 0.3, <3, 0, 0>, 0.5, <3.5, 0, 0>, 0.5
    pigment { color rgb <0.2, 0.7, 0.3> }
}

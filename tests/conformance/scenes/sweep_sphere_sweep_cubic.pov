// Conformance: a cubic_spline sphere sweep (through its inner points).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
sphere_sweep {
    cubic_spline 6,
    <-4, -1, 0>, 0.3, <-2.5, 0, 0>, 0.3, <-1, 1.5, 1>, 0.45, <1, -0.3, 0>, 0.25, <2.5, 1.2, -0.5>, 0.4, <4, 0, 0>, 0.3
    pigment { color rgb <0.9, 0.8, 0.2> }
}

// Conformance: linear sphere sweeps: a zigzag of equal spheres and a
// tapering chain whose radii change (the tangent cones between balls).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
sphere_sweep {
    linear_spline 5,
    <-3, -0.5, 0>, 0.3, <-2, 1, 0.5>, 0.3, <-1, -0.5, 0>, 0.3, <0, 1, 0.5>, 0.3, <1, -0.5, 0>, 0.3
    pigment { color rgb <0.9, 0.3, 0.2> }
}
sphere_sweep {
    linear_spline 4,
    <1.2, 1.8, 1>, 0.1, <2.2, 1.2, 0>, 0.5, <2.8, 0, -0.5>, 0.2, <2.5, -0.6, -1.5>, 0.35
    tolerance 1e-6
    pigment { color rgb <0.3, 0.4, 0.9> }
}

// Stability: lathes and a sor whose profiles meet the y axis with a flat
// (horizontal) tangent, where the surface normal turns to +-y and the
// radial direction is undefined; the camera looks almost straight down
// the axis of one of them so rays pass through and next to the axis.
// Scaled as a whole by S (tests/stability/CMakeLists.txt): the images at
// S = 1e-4 and 1e5 must agree with S = 1, the one at S = 1 with povray,
// and no pixel may be NaN (tests/unit/sweep_shapes_test.cpp).
//
//     frameray sweep_lathe_axis.pov +W160 +H120 Declare=S=1e-4
#version 3.7;
#ifndef (S) #declare S = 1; #end
global_settings { assumed_gamma 1.0 }

camera { location <0.02, 6, -2.5> * S look_at <0, 0.5, 0> * S angle 55 }
light_source { <-4, 9, -5> * S color rgb 1 }

plane { y, -1 * S pigment { color rgb <0.75, 0.75, 0.7> } }

// Bezier dome: flat top on the axis.
lathe {
    bezier_spline 8,
    <0, -1>, <0.7, -1>, <1, -0.5>, <1, 0>,
    <1, 0>, <1, 0.6>, <0.6, 1>, <0, 1>
    pigment { color rgb <0.9, 0.3, 0.2> }
    scale S
}
// Cubic profile through the axis at both ends with flat tangents.
lathe {
    cubic_spline 6,
    <0.5, -1.2>, <0, -1>, <0.6, -0.6>, <0.5, 0.4>, <0, 0.8>, <-0.5, 1>
    pigment { color rgb <0.2, 0.7, 0.3> }
    scale S translate <2.2, 0, 0.5> * S
}
// A sor whose radius shrinks to the axis at the top.
sor {
    6, <0.3, -1.4>, <0.6, -1>, <0.7, -0.3>, <0.4, 0.4>, <0, 0.8>, <0.2, 1.2>
    pigment { color rgb <0.3, 0.4, 0.9> }
    scale S translate <-2.2, 0, 0.5> * S
}

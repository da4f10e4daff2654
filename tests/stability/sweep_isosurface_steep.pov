// Stability: isosurfaces with steep or kinked functions: a high-frequency
// ripple on a sphere (|grad| up to ~2.7), a steep power function (|grad|
// up to 8 sqrt(3) ~ 13.9 at the container's corners) and a thin shell
// f = |r - 0.8| - 0.02 (gradient flips sign across it), each with
// max_gradient at or above the true bound. Scaled as a whole by S: the images at
// S = 1e-4 and 1e5 must agree with S = 1, the one at S = 1 with povray,
// and no pixel may be NaN (tests/unit/sweep_shapes_test.cpp).
// povray's isosurface `accuracy` is a distance along the world ray (its
// root search runs in the ray's world parameter), so below S = 1 the
// accuracy shrinks with the scene; with a fixed 0.001 povray's own S = 1e-4
// render matches its S = 1 render at 0.727 only (frameray: the same 0.727).
// Above S = 1 a fixed 0.001 is finer than needed (povray 0.9986 at 1e5).
//
//     frameray sweep_isosurface_steep.pov +W160 +H120 Declare=S=1e5
#version 3.7;
#ifndef (S) #declare S = 1; #end
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -6> * S look_at <0, 0.3, 0> * S angle 55 }
light_source { <-4, 9, -5> * S color rgb 1 }

plane { y, -1 * S pigment { color rgb <0.75, 0.75, 0.7> } }

isosurface {
    function { sqrt(x*x + y*y + z*z) - 0.8 + 0.03 * sin(40 * x) * sin(40 * y) }
    contained_by { sphere { 0, 1 } }
    max_gradient 3
    accuracy 0.001 * min(S, 1)
    pigment { color rgb <0.9, 0.3, 0.2> }
    scale S translate <-2, 0, 0> * S
}
isosurface {
    function { pow(x, 8) + pow(y, 8) + pow(z, 8) - 0.3 }
    contained_by { box { -1, 1 } }
    max_gradient 14
    accuracy 0.001 * min(S, 1)
    pigment { color rgb <0.2, 0.7, 0.3> }
    scale S
}
isosurface {
    function { abs(sqrt(x*x + y*y + z*z) - 0.8) - 0.02 }
    contained_by { box { <-1, -1, -1>, <1, 0.3, 1> } }
    max_gradient 1.1
    accuracy 0.001 * min(S, 1)
    pigment { color rgb <0.3, 0.4, 0.9> }
    scale S translate <2, 0, 0> * S
}

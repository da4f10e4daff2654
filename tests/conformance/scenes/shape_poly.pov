// Conformance: poly { order, <coefficients> } at orders 5, 6 and 7 (Glob_5
// and Twin_Glob from shapesq.inc, and an order-7 surface
// x⁶ + y⁶ + z⁶ - 3x²y²z² + 0.05x⁷ + 0.1y - 0.2 = 0 clipped by a box).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
#include "shapesq.inc"

camera { location <0, 3, -7> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, -1.5 pigment { color rgb <0.75, 0.75, 0.7> } }

object { Glob_5 clipped_by { box { <-1.5, -1, -1>, <0.5, 1, 1> } } rotate z * 90 scale 1.3 translate <-2.2, -0.2, 0>
    pigment { color rgb <0.9, 0.5, 0.2> } finish { phong 0.5 } }
object { Twin_Glob clipped_by { box { -2, 2 } } scale 0.9 rotate y * 30 translate <0.2, 0.2, 1.2>
    pigment { color rgb <0.3, 0.8, 0.35> } finish { phong 0.4 } }
poly {
    7,
    <0.05, 0, 0, 1, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, -3, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 1, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0.1, 0, 1, 0, 0, 0, 0, 0, -0.2>
    clipped_by { box { -1.1, 1.1 } }
    rotate <20, 30, 0> translate <2, 0, -0.5>
    pigment { color rgb <0.3, 0.5, 0.95> } finish { phong 0.3 }
}

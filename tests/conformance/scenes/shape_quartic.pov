// Conformance: quartic { <35 coefficients> } from shapesq.inc: a piriform,
// a torus written as a quartic, a bicorn and a devil's curve (clipped).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
#include "shapesq.inc"

camera { location <0, 3, -7> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, -1.5 pigment { color rgb <0.75, 0.75, 0.7> } }

object { Piriform rotate z * 90 scale 1.2 translate <-2.2, -0.3, 0.5>
    pigment { color rgb <0.9, 0.5, 0.2> } finish { phong 0.5 } }
object { Torus_40_12 scale 0.12 rotate x * -40 translate <0, 0.4, 1>
    pigment { color rgb <0.3, 0.8, 0.35> } finish { phong 0.4 } }
object { Bicorn clipped_by { box { -2, 2 } } translate <2, 0, 0.3>
    pigment { color rgb <0.3, 0.5, 0.95> } }
object { Devils_Curve clipped_by { sphere { 0, 1 } } scale 0.8 translate <0.3, -0.2, -2>
    pigment { color rgb <0.9, 0.85, 0.3> } finish { phong 0.3 } }

// Conformance: poly and cubic solved with `sturm`: Glob_5 (order 5) and
// Sinsurf (order 6) from shapesq.inc, and a cubic saddle.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
#include "shapesq.inc"

camera { location <0, 3, -7> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, -1.5 pigment { color rgb <0.75, 0.75, 0.7> } }

object { Glob_5 sturm clipped_by { box { <-1.5, -1, -1>, <0.5, 1, 1> } } rotate z * 90 scale 1.3 translate <-2.2, -0.2, 0>
    pigment { color rgb <0.9, 0.5, 0.2> } finish { phong 0.5 } }
object { Sinsurf sturm clipped_by { box { -1, 1 } } scale <1, 1, 0.2> rotate x * -70 scale 1.2 translate <0.3, 0.2, 1>
    pigment { color rgb <0.3, 0.8, 0.35> } finish { phong 0.4 } }
cubic {
    <1, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     -1, 0, 0, 0, 0, 0, 0, 0, -1, 0>
    sturm
    clipped_by { sphere { 0, 1.2 } }
    rotate x * -60 translate <2, 0.2, -0.5>
    pigment { color rgb <0.3, 0.5, 0.95> } finish { phong 0.4 }
}

// The object macros of shapes.inc, each called once with sizes that fit a
// cell of the grid (left to right, top to bottom): Wedge, Spheroid,
// Supertorus, Supercone, Connect_Spheres, Wire_Box (union and merge),
// Round_Box, Round_Cylinder, Round_Cone, Round_Cone2, Round_Cone3, Quad,
// Smooth_Quad, HF_Square, HF_Sphere, HF_Cylinder, HF_Torus,
// Bevelled_Text and Circle_Text.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "shapes.inc"
camera { orthographic location <0, 0, -30> look_at <0, 0, 0> right 15 * x up 11.25 * y }
light_source { <-30, 40, -60> rgb 1 }
light_source { <40, 10, -30> rgb 0.3 shadowless }
background { rgb <0.25, 0.3, 0.4> }
plane { z, 3 pigment { checker rgb 0.9 rgb 0.5 scale 1.25 } }
#declare T = texture { pigment { rgb <0.9, 0.7, 0.4> } finish { phong 0.5 } }
#macro Place(I)
  scale 0.75 rotate <-20, 35, 0>
  translate <-6.25 + 2.5 * mod(I, 6), 4.375 - 2.5 * div(I, 6), 0>
#end
#declare F = function { 0.5 + 0.25 * sin(x * 6) * cos(y * 5) }
object { intersection { Wedge(120) box { -1, 1 } } texture { T } Place(0) }
object { Spheroid(<0, 0, 0>, <1.2, 0.6, 0.8>) texture { T } Place(1) }
object { Supertorus(0.9, 0.3, 0.5, 1.5, 0.001, 1.5) texture { T } Place(2) }
object { Supercone(<0, -1, 0>, 1, 0.5, <0, 1, 0>, 0.3, 0.6) texture { T } Place(3) }
object { Connect_Spheres(<-0.8, -0.5, 0>, 0.4, <0.7, 0.6, 0>, 0.25) texture { T } Place(4) }
object { Wire_Box(<-1, -0.8, -0.6>, <1, 0.8, 0.6>, 0.08, 0) texture { T } Place(5) }
object { Wire_Box(<-1, -0.8, -0.6>, <1, 0.8, 0.6>, 0.08, 1) texture { T } Place(6) }
object { Round_Box(<-1, -0.8, -0.6>, <1, 0.8, 0.6>, 0.2, 0) texture { T } Place(7) }
object { Round_Cylinder(<0, -1, 0>, <0, 1, 0>, 0.8, 0.25, 1) texture { T } Place(8) }
object { Round_Cone(<0, -1, 0>, 0.9, <0, 1, 0>, 0.4, 0.15, 0) texture { T } Place(9) }
object { Round_Cone2(<0, -0.8, 0>, 0.7, <0, 0.8, 0>, 0.3, 0) texture { T } Place(10) }
object { Round_Cone3(<0, -0.8, 0>, 0.7, <0, 0.8, 0>, 0.3, 1) texture { T } Place(11) }
mesh { Quad(<-1, -1, 0>, <1, -1, 0>, <0.8, 1, 0>, <-0.6, 0.9, 0>) texture { T } Place(12) }
mesh { Smooth_Quad(<-1, -1, 0>, <-0.3, -0.3, -1>, <1, -1, 0>, <0.3, -0.3, -1>,
                   <0.8, 1, 0>, <0.3, 0.3, -1>, <-0.6, 0.9, 0>, <-0.3, 0.3, -1>) texture { T } Place(13) }
object { HF_Square(F, 0, 0, <20, 20>, 1, "", <-1, 0, -1>, <1, 0.8, 1>) texture { T } Place(14) }
object { HF_Sphere(F, 0, 0, <24, 24>, 1, "", <0, 0, 0>, 0.7, 0.4) texture { T } Place(15) }
object { HF_Cylinder(F, 0, 0, <24, 12>, 1, "", <0, -1, 0>, <0, 1, 0>, 0.6, 0.3) texture { T } Place(16) }
object { HF_Torus(F, 0, 0, <24, 12>, 1, "", 0.7, 0.25, 0.15) texture { T } Place(17) }
object { Bevelled_Text("timrom.ttf", "Ab", 4, 45, 0.05, 0.3, 0, 0) translate <-0.6, -0.3, 0> texture { T } Place(18) }
object { Circle_Text("timrom.ttf", "POV-Ray", 0.4, 0, 0.1, 0.8, 0, Align_Center, 0) texture { T } Place(19) }

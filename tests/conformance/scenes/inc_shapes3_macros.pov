// The object macros of shapes3.inc, each called once with sizes that fit a
// cell of the grid (left to right, top to bottom): Segment_of_Object,
// Segment_of_CylinderRing, Segment_of_Torus, Round_N_Tube_Polygon (ring
// and filled), Pyramid_N, Pyramid_N_AB, Column_N, Column_N_AB, Egg_Shape,
// Facetted_Sphere, Facetted_Egg_Shape, Facetted_Egg, Ring_Sphere,
// Round_Pyramid_N_in, Round_Pyramid_N_out, Rounded_Tube, Rounded_Tube_AB,
// Round_Cylinder_Tube, Round_Conic_Torus, Round_Conic_Prism and
// Half_Hollowed_Rounded_Cylinder1 and 2.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "shapes3.inc"
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
object { Segment_of_Object(sphere { 0, 1 }, 270) texture { T } Place(0) }
object { Segment_of_CylinderRing(1, 0.6, 1.2, 240) translate -0.6 * y texture { T } Place(1) }
object { Segment_of_Torus(0.8, 0.25, 300) texture { T } Place(2) }
object { Round_N_Tube_Polygon(6, 0.12, 0.8, 0.2, 0, 0) texture { T } Place(3) }
object { Round_N_Tube_Polygon(5, 0.12, 0.8, 0.2, 1, 1) texture { T } Place(4) }
object { Pyramid_N(6, 1, 0.4, 1.6) translate -0.8 * y texture { T } Place(5) }
object { Pyramid_N_AB(5, <0, -0.9, 0>, 1, <0.2, 0.9, 0>, 0.3) texture { T } Place(6) }
object { Column_N(8, 0.8, 1.6) translate -0.8 * y texture { T } Place(7) }
object { Column_N_AB(7, <0, -0.9, 0>, <0.3, 0.9, 0>, 0.6) texture { T } Place(8) }
object { Egg_Shape(1.15, 1.55) scale 0.6 texture { T } Place(9) }
object { Facetted_Sphere(4, 12) texture { T } Place(10) }
object { Facetted_Egg_Shape(4, 12, 1.15, 1.55) scale 0.6 texture { T } Place(11) }
object { Facetted_Egg(5, 16) scale 0.6 texture { T } Place(12) }
object { Ring_Sphere(0.9, 0.9, 0.05, 0.05, 6, 8) texture { T } Place(13) }
object { Round_Pyramid_N_in(5, <0, -0.9, 0>, 0.9, <0, 0.9, 0>, 0.4, 0.08, 1, 0) texture { T } Place(14) }
object { Round_Pyramid_N_out(4, <0, -0.9, 0>, 0.9, <0, 0.9, 0>, 0.4, 0.06, 0, 1) texture { T } Place(15) }
object { Rounded_Tube(1, 0.6, 0.1, 1.2, 0) translate -0.6 * y texture { T } Place(16) }
object { Rounded_Tube_AB(<0, -0.8, 0>, <0, 0.8, 0.2>, 0.9, 0.6, 0.1, 1) texture { T } Place(17) }
object { Round_Cylinder_Tube(<0, -0.8, 0>, <0, 0.8, 0>, 0.8, 0.15, 1, 0) texture { T } Place(18) }
object { Round_Conic_Torus(1.2, 0.5, 0.9, 0.15, 0) translate -0.6 * y texture { T } Place(19) }
object { Round_Conic_Prism(1.2, 0.5, 0.9, 1, 0.15, 0) translate -0.6 * y texture { T } Place(20) }
object { Half_Hollowed_Rounded_Cylinder1(2, 0.7, 0.1, 0.5, 0) texture { T } Place(21) }
object { Half_Hollowed_Rounded_Cylinder2(2, 0.7, 0.25, 0.1, 0.5, 1) texture { T } Place(22) }

// Conformance: a sor's first and last points only steer the slope at the
// ends, and povray 3.7 does not ask them to continue the rising heights:
// equal to the neighbour's (as the example objects/sor1.pov writes) or on
// the wrong side of it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -4.2> look_at <0, 0.55, 0> angle 50 }
light_source { <-3, 5, -4> rgb 1 }
light_source { <4, 2, -3> rgb 0.4 }
background { rgb <0.25, 0.3, 0.35> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.55 scale 0.5 } }
#declare Fin = finish { phong 0.6 }
// The first two points at one height.
sor { 6 <0.2, 0> <0.2, 0> <0.45, 0.4> <0.25, 0.8> <0.35, 1.1> <0.5, 1.3>
  pigment { rgb <1, 0.6, 0.3> } finish { Fin } translate -1.1*x }
// The last two at one height.
sor { 6 <0, -0.1> <0.3, 0> <0.45, 0.5> <0.2, 0.9> <0.3, 1.2> <0.4, 1.2>
  open pigment { rgb <0.4, 0.7, 1> } finish { Fin } }
// First point above the second, last below the one before it.
sor { 5 <0.3, 0.3> <0.35, 0.05> <0.2, 0.6> <0.4, 1.0> <0.1, 0.7>
  pigment { rgb <0.5, 1, 0.5> } finish { Fin } translate 1.1*x }

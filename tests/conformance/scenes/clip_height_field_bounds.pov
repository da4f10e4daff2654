// clipped_by bounds the object by its clipping objects' box, as povray:
// a ray that misses the height field's box does not see the part of the
// cylinder below it (the height field's inside reaches down without end).
// Left, an infinite quadric cylinder: its box is its part of the height
// field's box. Right, a finite open cylinder: the height field's box
// itself (objects/csg/hfclip.pov's column).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
camera { location <0, 6, -7> angle 40 right x*4/3 look_at <0, -0.5, 0> }
light_source { <60, 50, -100> rgb 1 }
#declare HF = height_field { function 32, 32 { 0.6 + 0.3 * sin(x * 9) * cos(y * 7) }
                             translate <-0.5, 0, -0.5> scale <4, 2, 4> }
object { Cylinder_Y clipped_by { object { HF } } translate -1.5*x
         pigment { rgb <1, 0.3, 0.2> } finish { ambient 0.2 } }
cylinder { <0, -10, 0>, <0, 10, 0>, 1 open clipped_by { object { HF } } translate 1.5*x
           pigment { rgb <0.2, 0.5, 1> } finish { ambient 0.2 } }

// A texture given to an object with a patterned texture would lie on top
// of it as a layer, which povray 3.7 refuses.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Tiled = sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } }
object { Tiled texture { pigment { rgbt 0.5 } } }

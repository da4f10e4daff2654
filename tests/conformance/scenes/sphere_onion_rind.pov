// Onion rings ending exactly on a sphere's surface (textures/pigments/
// cantelop.pov's melon rind): which colour a hit gets depends on the last
// bit of the hit point, so frameray must intersect spheres with povray's
// arithmetic (closest approach along the unit ray, then the half chord)
// and wrap onion as povray does.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <-2, 3, -3> angle 50 right x*image_width/image_height look_at <0.4, 0.10, 0> }
light_source { <-20, 30, -100> rgb 1 }
sphere { 0, 1 pigment { onion color_map { [0.5 rgb <1, 0.5, 0>] [0.5 rgb <0, 0, 1>] } } finish { ambient 0.3 } }
sphere { <1.5, 0, 1>, 0.5 pigment { onion color_map { [0.5 rgb <0, 1, 0>] [0.5 rgb <1, 0, 1>] } scale 0.5 translate <1.5, 0, 1> }
         finish { ambient 0.3 } }

// no_radiosity: the roof over the floor is seen by the camera but not by
// radiosity rays, so the floor still gathers the whole sky; max_sample
// limits the very bright sky ring each ray may bring back; rad_def.inc's
// presets set the rest.
#version 3.7;
#include "rad_def.inc"
global_settings { assumed_gamma 1 radiosity { Rad_Settings(Radiosity_Fast, off, off) recursion_limit 1 max_sample 1.5 } }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 55 }
sphere { 0, 1 hollow
  texture { pigment { gradient y color_map { [0.3 rgb <4, 3, 2>] [0.3 rgb <0.4, 0.6, 1>] } }
            finish { diffuse 0 emission 1 } }
  scale 10000 }
plane { y, 0 texture { pigment { rgb 0.8 } finish { diffuse 0.7 } } }
box { <-1, 1.5, -1>, <1, 1.6, 1> no_radiosity texture { pigment { rgb <1, 0.3, 0.2> } finish { diffuse 0 emission 0.8 } } }

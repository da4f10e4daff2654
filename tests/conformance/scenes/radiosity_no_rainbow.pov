// povray 3.7's radiosity rays see no rainbow: a white floor under a dark
// sky gathers light from directions a wide red rainbow covers; povray's
// floor stays grey (measured), frameray's turned red before.
#version 3.7;
global_settings { assumed_gamma 1 radiosity { count 200 recursion_limit 1 } }
camera { location <0, 0.01, 0> look_at <0, 0, 1> }
sky_sphere { pigment { rgb 0.2 } }
rainbow { angle 60 width 100 distance 1000 direction <0, 0, -1> jitter 0
  color_map { [0 rgbt <1, 0, 0, 0>] [1 rgbt <1, 0, 0, 0>] } }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }

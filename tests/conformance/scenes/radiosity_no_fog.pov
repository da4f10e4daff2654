// povray 3.7's radiosity rays see no fog: a white floor under a grey sky
// and a glowing blue ceiling, in a thick red fog (constant) and a ground
// fog. Camera rays are fogged (the far floor and the sky turn red); the
// light the floor gathers is the sky's and the ceiling's, unfogged
// (measured: the near floor stays grey-blue).
#version 3.7;
global_settings { assumed_gamma 1 radiosity { count 100 recursion_limit 1 } }
camera { location <0, 0.3, 0> look_at <0, 0, 2> }
sky_sphere { pigment { rgb 0.4 } }
fog { fog_type 1 distance 8 color rgb <1, 0, 0> }
fog { fog_type 2 distance 4 color rgb <0, 0.6, 0> fog_alt 0.5 fog_offset 0 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.8 } }
box { <-3, 3, 1>, <3, 3.2, 6> pigment { rgb <0.2, 0.3, 1> } finish { ambient 0 diffuse 0 emission 1 } }

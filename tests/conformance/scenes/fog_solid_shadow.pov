// A light with media_attenuation is dimmed by fog along its shadow rays,
// but not inside objects that are not hollow (povray 3.7, as in
// interior/media/hollow1.pov): the solid sphere's shadow (left) is
// lighter than the hollow one's (right).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 20, -100> }
fog { color rgb 0.5 distance 80 }
plane { y, -10 pigment { checker rgb <1, 1, 0>, rgb <0, 1, 0> scale 20 }
  finish { ambient 0.2 diffuse 0.8 } hollow }
sphere { <-26, 20, 0>, 25 pigment { rgbt <1, 1, 1, 0.8> }
  finish { ambient 0 diffuse 0 } interior { ior 1.05 } hollow no }
sphere { <26, 20, 0>, 25 pigment { rgbt <1, 1, 1, 0.8> }
  finish { ambient 0 diffuse 0 } interior { ior 1.05 } hollow yes }
light_source { <500, 600, -200>, color 40000 media_attenuation on }

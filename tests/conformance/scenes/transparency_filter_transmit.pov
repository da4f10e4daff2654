// Filter and transmit: the opaque share of ambient and diffuse light, the
// tinted and untinted light passing through, stacked transparent slabs,
// highlights unscaled by transparency.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> angle 45 }
light_source { <-5, 10, -15> rgb 1 }
plane { y, 0 pigment { checker rgb <0.95, 0.95, 0.9> rgb <0.2, 0.3, 0.6> scale 0.5 } }
plane { z, 3 pigment { checker rgb <0.9, 0.3, 0.2> rgb <0.9, 0.9, 0.6> scale 0.7 } finish { ambient 0.5 } }
sphere { <-2.2, 1, 0>, 0.8 pigment { rgbf <1, 0.3, 0.3, 0.7> } finish { phong 0.8 } no_shadow }
sphere { <-0.5, 1, 0>, 0.8 pigment { rgbt <0.3, 1, 0.3, 0.7> } finish { phong 0.8 } no_shadow }
sphere { <1.2, 1, 0>, 0.8 pigment { rgbft <0.3, 0.3, 1, 0.4, 0.4> } finish { specular 0.6 } no_shadow }
#for (i, 0, 5)
  box { <2.1, 0.2, -1 + i * 0.3>, <3, 2.2, -0.9 + i * 0.3> pigment { rgbt <1, 0.9, 0.6, 0.75> } finish { ambient 0.2 diffuse 0.3 } no_shadow }
#end

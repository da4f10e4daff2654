// Output_Alpha (+UA) under adaptive anti-aliasing (transmittance is
// averaged with the colour), with a 3.7 sky sphere that is clear toward
// the top (its transmit becomes the alpha channel), a layered texture and
// a texture map mixing clear and opaque entries.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2.5, -8> look_at <0, 0.9, 0> angle 45 }
sky_sphere { pigment { gradient y color_map { [0 rgbt <0.6, 0.7, 1, 0>] [0.5 rgbt <0.1, 0.2, 0.6, 1>] } } }
light_source { <-8, 12, -10> rgb 1 }
sphere { <-2.2, 1, 0>, 1 texture { pigment { rgbt <0.9, 0.4, 0.3, 0.6> } } texture { pigment { checker rgbt <1, 1, 1, 1> rgbt <0, 0, 1, 0.5> scale 0.3 } } }
sphere { <0, 1, 0>, 1 texture { checker texture { pigment { rgbt 1 } } texture { pigment { rgb <1, 0.5, 0> } } scale 0.4 } }
box { <1.2, 0, -0.8>, <3.2, 2, 0.8> pigment { rgbf <0.9, 0.9, 0.3, 0.7> } finish { phong 0.5 } rotate y * 20 }

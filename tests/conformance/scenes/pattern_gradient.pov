// Conformance: gradient with colour maps in both entry syntaxes and every
// wave type, frequency and phase.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { gradient x color_map { [0 rgb 0.2] [1 rgb 0.9] } scale 0.5 } }
box { <-3.6, 0, 0>, <-2.4, 2.5, 0.2> pigment { gradient y color_map { [0, 0.5 color rgb <1, 0, 0> color rgb <0, 1, 0>] [0.5, 1 color rgb <0, 0, 1> color rgb 1] } } }
box { <-2.2, 0, 0>, <-1, 2.5, 0.2> pigment { gradient y triangle_wave color_map { [0 rgb 0] [1 rgb <1, 0.8, 0.3>] } frequency 2 } }
box { <-0.8, 0, 0>, <0.4, 2.5, 0.2> pigment { gradient y sine_wave color_map { [0 rgb 0] [1 rgb <0.3, 0.8, 1>] } phase 0.3 } }
box { <0.6, 0, 0>, <1.8, 2.5, 0.2> pigment { gradient y scallop_wave color_map { [0 rgb 0] [1 rgb 1] } } }
box { <2, 0, 0>, <3.2, 2.5, 0.2> pigment { gradient y cubic_wave color_map { [0 rgb <0.5, 0, 0.5>] [1 rgb <1, 1, 0.5>] } frequency -1 } }
sphere { <-1.5, 0.6, -1.8>, 0.6 pigment { gradient x poly_wave 3 color_map { [0.2 rgb 0] [0.8 rgb <1, 0.5, 0>] } } }
sphere { <1.5, 0.6, -1.8>, 0.6 pigment { gradient y ramp_wave color_map { [0 rgb 0] [0.5 rgb <0, 1, 0>] [0.5 rgb <1, 0, 1>] [1 rgb 1] } scale 0.4 rotate z * 20 } }
sphere { <0, 0.5, -2.5>, 0.5 pigment { gradient x } }

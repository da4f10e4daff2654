// Conformance: ripples and waves as pigments, with frequency and phase.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { ripples color_map { [0 rgb <0.2, 0.2, 0.6>] [1 rgb <0.9, 0.9, 0.7>] } scale 0.7 } }
sphere { <-2.4, 1, 0>, 1 pigment { waves scale 0.2 } }
sphere { <0, 1, 0>, 1 pigment { ripples frequency 3 phase 0.3 scale 0.5 } }
sphere { <2.4, 1, 0>, 1 pigment { waves frequency 2.5 phase 0.7 color_map { [0 rgb <0, 0, 0.3>] [1 rgb <0.5, 1, 1>] } } }

// Conformance: wave types, frequency and phase on gradient and bozo.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { gradient x sine_wave frequency 0.7 phase 0.2 color_map { [0 rgb <0.2, 0.2, 0.6>] [1 rgb <0.9, 0.9, 0.7>] } } }
sphere { <-3, 1, 0>, 0.8 pigment { gradient y scallop_wave frequency 3 } }
sphere { <-1, 1, 0>, 0.8 pigment { gradient y cubic_wave frequency 2 phase 0.1 } }
sphere { <1, 1, 0>, 0.8 pigment { bozo poly_wave 3 scale 0.3 } }
sphere { <3, 1, 0>, 0.8 pigment { bozo triangle_wave frequency 4 scale 0.5 } }

// Conformance: marble and wood with and without turbulence (their own
// turbulence handling, triangle wave by default).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { wood turbulence <0.1, 0.05, 0.2> color_map { [0 rgb <0.8, 0.5, 0.2>] [1 rgb <0.4, 0.2, 0.05>] } scale 0.6 } }
sphere { <-2.4, 1, 0>, 1 pigment { marble } }
sphere { <0, 1, 0>, 1 pigment { marble turbulence 1.2 octaves 4 omega 0.6 lambda 2.5 color_map { [0 rgb 1] [0.8 rgb <0.3, 0.3, 0.5>] [1 rgb 0] } scale 0.6 } }
sphere { <2.4, 1, 0>, 1 pigment { wood turbulence 0.3 ramp_wave scale 0.3 rotate x*80 } }

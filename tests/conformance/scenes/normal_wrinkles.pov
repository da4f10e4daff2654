// Conformance: wrinkles normal, plain, scaled and with turbulence.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { rgb <0.8, 0.7, 0.5> } normal { wrinkles 0.6 scale 0.5 } }
sphere { <-1.3, 1, 0>, 1 pigment { rgb 0.9 } normal { wrinkles scale 0.3 } finish { specular 0.5 } }
sphere { <1.3, 1, 0>, 1 pigment { rgb <0.4, 0.6, 1> } normal { wrinkles 1 turbulence 0.3 scale 0.5 } }

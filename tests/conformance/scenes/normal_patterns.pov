// Conformance: colour-mapped patterns used as normals (sampled slopes):
// granite, marble with turbulence, gradient, onion; accuracy.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { rgb <0.8, 0.7, 0.5> } normal { gradient x 0.5 scale 0.7 } }
sphere { <-2.4, 1, 0>, 1 pigment { rgb 0.9 } normal { granite 0.3 scale 2 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.4, 0.6, 1> } normal { marble 0.8 turbulence 0.5 scale 0.5 } }
sphere { <2.4, 1, 0>, 1 pigment { rgb <1, 0.5, 0.3> } normal { onion 0.6 accuracy 0.05 scale 0.3 } }

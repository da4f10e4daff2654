// Conformance: bumps and dents normals, bump size after the pattern and
// as bump_size, scaled and in a texture.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { rgb <0.8, 0.7, 0.5> } normal { bumps 0.8 scale 0.4 } }
sphere { <-2.4, 1, 0>, 1 pigment { rgb 0.9 } normal { bumps scale 0.2 } finish { phong 0.6 } }
sphere { <0, 1, 0>, 1 texture { pigment { rgb <0.4, 0.6, 1> } normal { dents bump_size 2 scale 0.3 } } }
sphere { <2.4, 1, 0>, 1 pigment { rgb <1, 0.5, 0.3> } normal { bumps 1.5 scale <0.1, 0.5, 0.5> rotate 30*z } }

// crand: each light's diffuse term loses crand times a random number in
// [0, 1) at every shading point (two lights, so two numbers). povray's
// numbers differ from render to render, so the manifest compares local
// means (--blur) instead of pixels.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 0.9, 0> angle 48 }
light_source { <-10, 20, -15> rgb 1 }
light_source { <12, 8, -10> rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.45 scale 2 } finish { crand 0.08 } }
sphere { <-2.5, 1, 0>, 1 pigment { rgb <0.9, 0.5, 0.3> } finish { diffuse 0.7 crand 0.15 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.3, 0.6, 0.9> } finish { crand 0.05 phong 0.5 } }
box { <1.6, 0, -0.8>, <3.4, 1.8, 0.8> pigment { rgb 0.85 } finish { ambient 0.2 diffuse 0.5 crand 0.3 } rotate y * 25 }

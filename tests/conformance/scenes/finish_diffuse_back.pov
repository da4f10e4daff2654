// povray 3.7's two-value diffuse: `diffuse A, B` lights the surface with B
// of the lights on its far side (no highlights from them): thin sheets lit
// from behind, a translucent sphere whose shadow ray crosses its own far
// side, and double_illuminate, which wins over the back value.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -9> look_at <0, 1.2, 0> angle 50 }
light_source { <-6, 10, -12> rgb 0.7 }
light_source { <4, 6, 14> rgb <1, 0.9, 0.7> }
plane { y, 0 pigment { rgb 0.6 } }
// Thin sheets facing the camera, the second light behind them.
box { <-4.2, 0.2, 0>, <-2.2, 2.6, 0.02> pigment { rgb <0.9, 0.8, 0.4> } finish { diffuse 0.6, 0.5 } }
box { <-2, 0.2, 0>, <0, 2.6, 0.02> pigment { rgb <0.4, 0.8, 0.5> } finish { diffuse albedo 0.5, 0.4 brilliance 2 phong 0.5 } }
disc { <1.2, 1.4, 0>, <0, 0, -1>, 1 pigment { rgb <0.9, 0.4, 0.4> } finish { diffuse 0.5, 0.6 } double_illuminate }
sphere { <3.3, 1.1, 0>, 1 pigment { rgbt <0.6, 0.7, 1, 0.4> } finish { diffuse 0.6, 0.4 specular 0.4 } }

// Conformance: julia_fractal, the 3-D slice w = 0 of a 4-D Julia set:
// quaternion sqr (the defaults), quaternion cube and hypercomplex sqr,
// with max_iteration, textured and moved like any object. A high precision
// (march step 1/200): at the default 20 povray and frameray miss
// different thin filaments between their steps.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -7> look_at 0 angle 45 }
light_source { <-4, 6, -8> rgb 1 }
light_source { <5, 2, -6> rgb 0.4 }
background { rgb <0.2, 0.22, 0.3> }
julia_fractal { <-0.4, 0.3, 0.2, 0> precision 200
  pigment { rgb <1, 0.6, 0.3> } finish { phong 0.5 }
  rotate <20, 30, 0> translate <-1.8, 0.7, 0> }
julia_fractal { <-0.2, 0.5, 0.1, 0> quaternion cube max_iteration 8 precision 200
  pigment { rgb <0.4, 0.9, 0.5> }
  scale 0.9 rotate <-30, 10, 0> translate <1.6, 0.8, 0> }
julia_fractal { <0.3, -0.2, 0.4, -0.1> hypercomplex sqr max_iteration 6 precision 200
  pigment { rgb <0.5, 0.6, 1> } finish { specular 0.4 }
  scale 0.8 rotate <60, 0, -40> translate <0, -1.1, 0> }

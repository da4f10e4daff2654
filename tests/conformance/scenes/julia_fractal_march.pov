// Conformance: julia_fractal at povray's default precision 20, where its
// marcher's distance-estimate steps decide which thin filaments show:
// quaternion sqr, hypercomplex sqr, and hypercomplex cube (which povray 3.7
// iterates as a square, with other steps), lit so that the fractals shadow
// themselves (shadow rays leaving a surface from just inside meet it
// first, and so nothing, as in povray).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -7> look_at 0 angle 45 }
light_source { <-4, 6, -8> rgb 1 }
light_source { <5, 2, -6> rgb 0.4 }
background { rgb <0.2, 0.22, 0.3> }
julia_fractal { <0.49, 0.5, -0.34, 0.1> quaternion max_iteration 7
  pigment { rgb <1, 0.6, 0.3> } finish { phong 0.5 }
  rotate <110, 50, -60> translate <-1.8, 0.7, 0> }
julia_fractal { <-0.745, 0, 0.113, 0.05> hypercomplex max_iteration 9
  pigment { rgb <0.4, 0.9, 0.5> } finish { phong 0.9 phong_size 20 }
  scale <0.6, 1.2, 0.6> rotate <135, -30, 0> translate <1.7, 0.8, 0> }
julia_fractal { <-0.745, 0, 0.113, 0.05> hypercomplex cube max_iteration 9
  pigment { rgb <0.5, 0.6, 1> } finish { specular 0.4 }
  scale <0.6, 1.2, 0.6> rotate <135, -30, 0> translate <0, -1.2, 0> }

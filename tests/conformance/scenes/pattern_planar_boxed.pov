// Conformance: planar and boxed value functions with transformations.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { boxed color_map { [0 rgb <0.3, 0.2, 0.1>] [1 rgb <0.9, 0.8, 0.6>] } scale 3 } }
box { <-3, 0, 0>, <-0.5, 2.5, 0.3> pigment { planar color_map { [0 rgb 0] [1 rgb <0.2, 0.9, 0.4>] } scale 0.6 translate y * 1.2 } }
sphere { <1.6, 1.2, 0>, 1.2 pigment { boxed frequency 3 color_map { [0 rgb <0, 0, 0.3>] [1 rgb <1, 0.6, 0.2>] } rotate <20, 30, 0> scale 1.2 translate <1.6, 1.2, 0> } }
sphere { <0, 0.5, -2>, 0.5 pigment { planar sine_wave frequency 4 } }

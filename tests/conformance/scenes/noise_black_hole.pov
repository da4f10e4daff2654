// Conformance: warp { black_hole } with strength, falloff and inverse.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { checker rgb <0.2, 0.2, 0.6>, rgb <0.9, 0.9, 0.7> scale 0.5 warp { black_hole <0, 0, 2>, 3 } } }
sphere { <-2.4, 1, 0>, 1 pigment { gradient y warp { black_hole <-2.4, 1, -1>, 1.5 strength 0.7 falloff 3 } scale 0.3 } }
sphere { <0, 1, 0>, 1 pigment { bozo scale 0.2 warp { black_hole <0, 1, -1>, 1.2 inverse } } }
sphere { <2.4, 1, 0>, 1 pigment { onion warp { black_hole <0.3, 0.2, -0.8>, 1 strength 2 falloff 1 } color_map { [0 rgb <0.1, 0.3, 0>] [1 rgb <1, 1, 0>] } scale 0.4 translate <2.4, 1, 0> } }

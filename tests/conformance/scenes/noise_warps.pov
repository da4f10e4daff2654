// Conformance: warp { turbulence } and warp { repeat offset flip },
// interleaved with transformations (the later item acts first).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { bozo scale 0.3 warp { repeat x * 1.5 offset <0.2, 0, 0.7> flip <0, 0, 1> } color_map { [0 rgb <0.2, 0.2, 0.6>] [1 rgb <0.9, 0.9, 0.7>] } } }
sphere { <-2.4, 1, 0>, 1 pigment { gradient y warp { turbulence 0.5 octaves 3 } scale 0.4 } }
sphere { <0, 1, 0>, 1 pigment { onion scale 0.3 warp { turbulence <0.3, 0.6, 0.1> lambda 2.2 omega 0.4 } rotate 40*x color_map { [0 rgb <0.1, 0.3, 0>] [1 rgb <1, 1, 0>] } } }
sphere { <2.4, 1, 0>, 1 pigment { checker rgb 1, rgb <1, 0, 0> scale 0.25 warp { repeat y*0.5 flip y } warp { turbulence 0.2 } } }

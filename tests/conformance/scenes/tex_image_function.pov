// `function W, H { }` images (povray 3.7, measured with pigment functions):
// pixel (i, j), j = 0 the top row, holds f(i / (W - 1), j / (H - 1), 0) as
// 16 bits (values past 1 wrap), taken as working-space values; in
// image_map, image_pattern and bump_map.
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { location <0, 1.6, -5> look_at <0, 0.3, 0> angle 55 }
light_source { <-4, 7, -6> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.3 }
plane { y, -1 pigment { rgb <0.75, 0.72, 0.68> } }

#declare Ripple = function { 0.5 + 0.4 * sin(x * 12) * cos(y * 9) }
box { <0, 0, 0>, <1, 1, 0.1>
  pigment { image_map { function 40, 30 { x * 0.9 + y * 0.3 } } }
  scale 1.6 rotate y * 15 translate <-3, -0.6, 0.5> }
box { <0, 0, 0>, <1, 1, 0.1>
  pigment { image_pattern { function 64, 64 { Ripple(x, y, z) } interpolate 2 }
    color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb <0.9, 0.9, 0.8>] [1 rgb <0.8, 0.3, 0.1>] } }
  scale 1.6 rotate y * -10 translate <-0.8, -0.6, 0.3> }
sphere { 0, 0.9
  pigment { rgb <0.9, 0.85, 0.6> }
  normal { bump_map { function 64, 32 { Ripple(x, y, z) } map_type 1 interpolate 2 bump_size 40 } }
  finish { phong 0.6 } translate <2, 0, 0.6> }

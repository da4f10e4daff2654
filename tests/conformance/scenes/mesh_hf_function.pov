#version 3.7;
global_settings { assumed_gamma 1.0 }
// Height fields from functions: sampled at x = i / (W - 1), y = j / (H - 1),
// the value stored as povray keeps it (times 65535, truncated to 16 bits,
// so 1.2 wraps round to 0.2).
camera { location <0, 2.4, -3> look_at <0, 0.1, 0> angle 45 }
light_source { <-3, 6, -4> color rgb 1 }
light_source { <4, 3, -1> color rgb 0.3 }
background { color rgb <0.3, 0.4, 0.6> }
height_field {
  function 24, 18 { 0.5 + 0.3 * sin(x * 8) * cos(y * 6) }
  translate <-0.5, 0, -0.5>
  scale <1.3, 0.5, 1.3>
  translate <-0.7, 0, 0>
  pigment { color rgb <1, 0.8, 0.5> }
}
#declare F = function { 0.6 * x + 0.7 * y * y }
height_field {
  function 12, 12 { F(x, y, 0) }
  smooth
  translate <-0.5, 0, -0.5>
  scale <1.3, 0.5, 1.3>
  rotate y * -30
  translate <0.8, 0, 0.2>
  pigment { color rgb <0.5, 0.8, 1> }
}

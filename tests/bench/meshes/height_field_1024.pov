#version 3.7;
global_settings { assumed_gamma 1.0 }
// Benchmark: a 1024 x 1024 smooth height field (about 2 million triangles)
// from a function, with a shadow-casting light.
camera { location <0, 2.2, -2.6> look_at <0, 0.1, 0> angle 45 }
light_source { <-3, 6, -4> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
height_field {
  function 1024, 1024 { 0.5 + 0.2 * sin(x * 40) * cos(y * 35) + 0.1 * sin((x + y) * 90) }
  smooth
  translate <-0.5, 0, -0.5>
  scale <2.4, 0.5, 2.4>
  pigment { color rgb <0.6, 0.9, 0.5> }
}

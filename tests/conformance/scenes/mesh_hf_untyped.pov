#version 3.7;
global_settings { assumed_gamma 1.0 }
// A height field from a file named without its type keyword: povray 3.7
// reads the type from the file (the example advanced/crater/crater.pov
// writes `height_field { "crater_dat.png" smooth ... }`). A PNG and a
// Targa, both with the type left out (a string literal: povray refuses a
// string identifier there).
camera { location <0, 2.4, -2.8> look_at <0, 0.1, 0> angle 50 }
light_source { <-3, 6, -4> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
#declare Ground = pigment { gradient y color_map { [0 color rgb <0.2, 0.5, 0.1>] [1 color rgb 1] } scale 0.6 }
height_field {
  "mesh_hf_bumps.png" smooth
  translate <-0.5, 0, -0.5>
  scale <1.6, 0.6, 1.8>
  pigment { Ground }
  translate -0.85*x
}
height_field {
  "mesh_hf_bumps.tga"
  translate <-0.5, 0, -0.5>
  scale <1.6, 0.6, 1.8>
  pigment { Ground }
  translate 0.85*x
}

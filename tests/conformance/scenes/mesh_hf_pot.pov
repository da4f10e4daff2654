#version 3.7;
global_settings { assumed_gamma 1.0 }
// A height field from a Fractint pot file: a GIF twice as wide as the
// field, each row's left half the heights' high bytes, its right half the
// low bytes (the example advanced/mtmand.pov reads mtmand.pot).
camera { location <0, 2.2, -2.6> look_at <0, 0.1, 0> angle 45 }
light_source { <-3, 6, -4> color rgb 1 }
light_source { <4, 3, -1> color rgb 0.3 }
background { color rgb <0.3, 0.4, 0.6> }
height_field {
  pot "mesh_hf_heights.pot"
  translate <-0.5, 0, -0.5>
  scale <2.4, 0.6, 1.8>
  pigment { gradient y color_map { [0 color rgb <0.2, 0.5, 0.1>] [0.5 color rgb <0.6, 0.5, 0.3>] [1 color rgb 1] } scale 0.6 }
}

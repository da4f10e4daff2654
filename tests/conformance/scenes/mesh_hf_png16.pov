#version 3.7;
global_settings { assumed_gamma 1.0 }
// A height field from a 16-bit PNG that povray rendered (the source of
// mesh_hf_bumps.png at +FN16): heights are the red channel's 16 bits.
// Smooth, steep, and cut by CSG: the height field's inside is below its
// surface, over the unit square.
camera { location <0, 2.2, -2.6> look_at <0, 0.1, 0> angle 45 }
light_source { <-3, 6, -4> color rgb 1 }
light_source { <4, 3, -1> color rgb 0.3 }
background { color rgb <0.3, 0.4, 0.6> }
intersection {
  height_field {
    png "mesh_hf_bumps16.png" smooth
    translate <-0.5, 0, -0.5>
    scale <2.4, 1.2, 1.8>
    pigment { color rgb <0.9, 0.7, 0.4> }
  }
  sphere { <0, 0, 0>, 1.1 pigment { color rgb <0.4, 0.6, 1> } }
}

// A GIF palette image: filter and transmit per palette index, filter all
// overridden by an index, over a lit floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -4.5> look_at <0, 0.2, 0> angle 55 }
light_source { <-3, 6, -5> color rgb 1 }
plane { y, -1 pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.3, 0.2, 0.1> } }
box { <0, 0, 0>, <1, 1, 0.01>
  pigment { image_map { gif "image_palette.gif" } }
  scale 1.3 translate <-2.1, -0.8, 0>
}
box { <0, 0, 0>, <1, 1, 0.01>
  pigment { image_map { gif "image_palette.gif" filter 1, 0.9 transmit 4, 1 } }
  scale 1.3 translate <-0.65, -0.8, 0>
}
box { <0, 0, 0>, <1, 1, 0.01>
  pigment { image_map { gif "image_palette.gif" filter all 0.7 filter 2, 0 transmit 0, 0.5 interpolate 2 } }
  scale 1.3 translate <0.8, -0.8, 0>
}
sphere { <0, 1.2, 1.5>, 0.7
  pigment { image_map { gif "image_palette.gif" map_type 1 transmit 3, 0.8 } }
}

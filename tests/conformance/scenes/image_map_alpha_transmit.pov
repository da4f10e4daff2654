// PNG alpha as transmit (1 - alpha, on top of transmit all), filter all,
// transmit all and premultiplied, over a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -4.5> look_at <0, 0.3, 0> angle 55 }
light_source { <-3, 6, -5> color rgb 1 }
plane { y, -1 pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.2, 0.3, 0.5> } }
box { <0, 0, 0>, <1, 1, 0.01>
  pigment { image_map { png "image_alpha.png" } }
  translate <-2, -0.6, 0>
}
box { <0, 0, 0>, <1, 1, 0.01>
  pigment { image_map { png "image_alpha.png" transmit all 0.3 } }
  translate <-0.9, -0.6, 0>
}
box { <0, 0, 0>, <1, 1, 0.01>
  pigment { image_map { png "image_alpha.png" filter all 0.6 } }
  translate <0.2, -0.6, 0>
}
box { <0, 0, 0>, <1, 1, 0.01>
  pigment { image_map { png "image_alpha.png" premultiplied on gamma 1.8 } }
  translate <1.3, -0.6, 0>
}
box { <0, 0, 0>, <3.2, 1, 0.01>
  pigment { image_map { ppm "image_grid.ppm" transmit all 0.5 } scale <3.2, 1, 1> }
  translate <-1.6, 0.6, 0.8>
}

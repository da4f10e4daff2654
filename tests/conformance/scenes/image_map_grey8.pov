// image_map of an 8-bit grey PNG (no gAMA: sRGB): povray keeps the decoded
// image in an 8-bit grey buffer, truncating each level (a value of 10
// decodes to 0.77/255 and is kept as 0). The dark levels show it after the
// sRGB output encoding. Left: the file's own gamma; right: `gamma 2.2`.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <1, 0.5, -1> look_at <1, 0.5, 0> right 2*x up y }
plane { z, 0
  pigment { image_map { png "image_grey8.png" } }
  finish { emission 1 diffuse 0 ambient 0 }
  clipped_by { box { <0, 0, -1>, <1, 1, 1> } }
}
plane { z, 0
  pigment { image_map { png "image_grey8.png" gamma 2.2 } translate x }
  finish { emission 1 diffuse 0 ambient 0 }
  clipped_by { box { <1, 0, -1>, <2, 1, 1> } }
}

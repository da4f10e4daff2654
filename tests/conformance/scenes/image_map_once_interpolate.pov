// image_map once with interpolate 2 (bilinear) and 4 (normalized
// distance) on a small image magnified, beside the plain lookup.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -5> look_at <0, 0, 0> right x*4.4 up y*3.3 }
background { rgb <0.2, 0.25, 0.4> }
#declare Window = box { <-0.3, -0.3, -1>, <1.5, 1.5, 1> }
plane { z, 0
  pigment { image_map { png "image_grid.png" once } scale 1.2 translate <-2, 0.2, 0> }
  finish { ambient 1 diffuse 0 }
  clipped_by { object { Window translate <-2, 0.2, 0> } }
}
plane { z, 0
  pigment { image_map { png "image_grid.png" once interpolate 2 } scale 1.2 translate <-0.6, 0.2, 0> }
  finish { ambient 1 diffuse 0 }
  clipped_by { object { Window translate <-0.6, 0.2, 0> } }
}
plane { z, 0
  pigment { image_map { png "image_grid.png" once interpolate 4 } scale 1.2 translate <0.8, 0.2, 0> }
  finish { ambient 1 diffuse 0 }
  clipped_by { object { Window translate <0.8, 0.2, 0> } }
}
plane { z, 0.01
  pigment { image_map { ppm "image_grid.ppm" interpolate 2 } scale 0.9 translate <-0.1, 0, 0> }
  finish { ambient 1 diffuse 0 }
  clipped_by { box { <-2.1, -1.6, -1>, <2.1, 0, 1> } }
}

// image_map map_type 1 (spherical) on spheres, one seen from above.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0, 0> angle 50 }
light_source { <-4, 5, -6> color rgb 1 }
sphere { 0, 1
  pigment { image_map { png "image_grid.png" map_type 1 } }
  rotate y*30 translate <-1.2, 0, 0>
}
sphere { 0, 1
  pigment { image_map { png "image_grid.png" map_type 1 interpolate 2 } }
  rotate x*-70 translate <1.2, 0, 0>
}

// image_map, planar (map_type 0): a PNG (sRGB) tiled on a tilted plane and
// a PPM (linear) once on a box face, with a light and a gamma-1 scene.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.3, 0> angle 50 }
light_source { <-3, 6, -6> color rgb 1 }
plane { y, -1
  pigment { image_map { png "image_grid.png" } scale <2, 1, 1> rotate x*90 }
}
box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5>
  pigment { image_map { ppm "image_grid.ppm" once } translate <-0.5, -0.5, 0> scale 1.2 }
  rotate y*25 translate <0.8, 0, 0>
}
sphere { <-1.3, 0.1, 0>, 0.8
  pigment { image_map { "image_grid.png" } scale 0.5 rotate z*20 }
  finish { phong 0.5 }
}

// normal { bump_map }: planar on a floor (plain and interpolated), on a
// box, spherical on a sphere, and palette indices (use_index) on a
// panel, with bump_size inside and outside.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0, 0> angle 50 }
light_source { <-4, 6, -3> color rgb 1 }
light_source { <5, 3, -6> color rgb 0.4 }
plane { y, -1
  pigment { rgb <0.8, 0.75, 0.6> }
  normal { bump_map { png "image_heights.png" bump_size 3 } rotate x*90 scale 1.5 }
  finish { phong 0.4 }
}
box { <-0.7, -1, -0.7>, <0.7, 0.4, 0.7>
  pigment { rgb <0.5, 0.7, 0.9> }
  normal { bump_map { png "image_heights.png" interpolate 2 } bump_size -2 translate <-0.5, -0.5, 0> scale 1.4 }
  finish { specular 0.5 }
  rotate y*30 translate <1.5, 0, 0.5>
}
sphere { <-1.4, 0, 0>, 1
  pigment { rgb <0.9, 0.5, 0.4> }
  normal { bump_map { png "image_heights.png" map_type 1 interpolate 4 bump_size 4 } rotate y*40 }
  finish { phong 0.6 }
}
box { <0, 0, 0>, <1, 1, 0.05>
  pigment { rgb 0.9 }
  normal { bump_map { gif "image_palette.gif" use_index bump_size 0.1 } }
  scale 0.9 rotate x*20 translate <-0.2, 0.5, 1.5>
}

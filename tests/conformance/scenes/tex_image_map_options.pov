// Image-map options measured with povray 3.7: `interpolate 3` (an
// undocumented Catmull-Rom bicubic through the texel centres, wrapping)
// on image_map, bump_map and material_map, and the map_type values
// other than 0, 1, 2 and 5, which image_pattern, bump_map and
// material_map take as planar (image_map refuses them).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.8, -5.5> look_at <0, 0.3, 0> angle 55 }
light_source { <-4, 7, -6> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.3 }
plane { y, -1 pigment { rgb <0.75, 0.72, 0.68> } }

box { <0, 0, 0>, <1, 1, 0.1>
  pigment { image_map { png "image_grid.png" interpolate 3 } }
  scale 1.5 rotate y * 15 translate <-3, -0.6, 0.5> }
sphere { 0, 0.8
  pigment { image_map { gif "image_palette.gif" map_type 1 interpolate 3 } }
  rotate y * -20 translate <-0.6, 0, 0.8> }
box { <0, 0, 0>, <1, 1, 0.1>
  pigment { image_map { png "image_alpha.png" interpolate 3 } }
  scale 1.3 translate <-3.2, -0.9, -1.2> }
sphere { 0, 0.8
  pigment { rgb <0.9, 0.85, 0.6> }
  normal { bump_map { png "image_heights.png" map_type 7 interpolate 3 bump_size 4 } scale 0.5 }
  finish { phong 0.6 } translate <1.4, 0, 0.6> }
box { <-0.7, -0.7, -0.7>, <0.7, 0.7, 0.7>
  pigment { image_pattern { png "image_heights.png" map_type 3 }
    color_map { [0 rgb <0.1, 0.2, 0.6>] [1 rgb <1, 0.9, 0.4>] } }
  rotate <-20, 30, 0> translate <3.2, -0.2, 1> }
box { <0, 0, 0>, <1, 1, 0.1>
  texture { material_map { gif "image_palette.gif" map_type 4 interpolate 3
    texture { pigment { rgb <0.9, 0.2, 0.1> } }
    texture { pigment { rgb <0.2, 0.7, 0.2> } finish { phong 0.8 } }
    texture { pigment { rgb <0.1, 0.3, 0.9> } }
    texture { pigment { rgb <0.95, 0.9, 0.3> } }
    texture { pigment { rgb 1 } } } }
  scale 1.4 rotate y * -15 translate <0.4, -0.9, -1.4> }

// material_map: a palette PNG picks textures by palette index (7 indices,
// 5 textures: index 5 takes the last texture, index 6 wraps to 1), the
// true-colour image_grid.png by its red byte (modulo 5), a GIF wrapped
// spherically, `once` (texture 0 outside the image), textures with their
// own finishes, normals and patterns, and transformations after the map.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.6, -5> look_at <0, 0.4, 0> angle 60 }
light_source { <-4, 7, -6> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.4 }
plane { y, -1 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.35, 0.3, 0.3> } }

#declare TRed = texture { pigment { rgb <0.9, 0.15, 0.1> } finish { phong 0.6 } }
#declare TBlue = texture { pigment { rgb <0.1, 0.25, 0.9> } normal { bumps 0.6 scale 0.05 } }
#declare TStripes = texture { pigment { gradient x color_map { [0 rgb 1] [0.5 rgb 1] [0.5 rgb <0.2, 0.6, 0.2>] } scale 0.1 translate x * 0.025 } }
#declare TGold = texture { pigment { rgb <0.9, 0.75, 0.2> } finish { specular 0.7 roughness 0.02 reflection 0.2 } }
#declare TGrey = texture { pigment { rgb 0.5 } }

box { <0, 0, 0>, <1, 1, 0.1>
  texture { material_map { png "material_palette.png"
    texture { TRed } texture { TBlue } texture { TStripes } texture { TGold } texture { TGrey } } }
  scale 1.6 rotate y * 20 translate <-2.6, -0.3, 0>
}
box { <0, 0, 0>, <1, 1, 0.1>
  texture { material_map { png "image_grid.png"
    texture { TRed } texture { TBlue } texture { TGold } texture { TStripes } texture { TGrey } }
    scale <0.5, 1, 1> }
  scale 1.6 translate <-0.8, -0.3, 0>
}
sphere { 0, 0.8
  texture { material_map { gif "image_palette.gif" map_type 1
    texture { TGold } texture { TBlue } texture { TRed } texture { TGrey } texture { TStripes } } }
  rotate y * -30 translate <1.8, 0.5, 0.6>
}
box { <-1, -1, 0>, <2, 2, 0.1>
  texture { material_map { png "material_palette.png" once
    texture { TGrey } texture { TRed } texture { TBlue } texture { TGold } texture { TStripes } texture { TRed } } }
  scale 0.5 rotate x * 70 translate <-0.2, -0.95, -1.6>
}

// List-pattern textures: checker, hexagon and brick given whole textures
// (normals and finishes differ per cell); transformations move the cells
// and the textures in them; a tiles texture with layered tiles.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 55 }
light_source { <-5, 10, -7> rgb 1 }
background { rgb <0.5, 0.6, 0.8> }
#declare T_Wood = texture { pigment { wood scale 0.2 } finish { phong 0.4 } }
plane { y, 0
  texture {
    checker
      texture { pigment { rgb <0.9, 0.85, 0.7> } finish { reflection 0.25 } }
      texture { T_Wood }
    scale 1.5 rotate 20 * y
  }
}
sphere { <-1.6, 1, 0>, 1
  texture { hexagon
    texture { pigment { rgb <1, 0.3, 0.2> } normal { dents 0.8 scale 0.1 } }
    texture { pigment { gradient x color_map { [0 rgb 0] [1 rgb <0.2, 1, 0.4>] } scale 0.1 } }
    texture { pigment { rgb <0.3, 0.4, 1> } finish { phong 1 } }
    scale 0.25 rotate <90, 0, 20>
  }
}
box { <0.4, 0, -0.8>, <2.4, 1.6, 0.8>
  texture { brick
    texture { pigment { rgb 0.8 } }, texture { pigment { granite scale 0.5 } finish { specular 0.5 } }
    brick_size <0.5, 0.2, 0.25> mortar 0.03 warp { turbulence 0.05 }
  }
}
sphere { <0, 0.4, -2>, 0.4
  texture { tiles {
      texture { pigment { rgb <1, 1, 0> } }
      texture { pigment { gradient y color_map { [0 rgbt <0, 0, 1, 0.3>] [1 rgbt 1] } scale 0.1 } }
      tile2 texture { pigment { rgb <0.6, 0, 0.8> } finish { phong 0.8 } }
    }
    scale 0.15
  }
}

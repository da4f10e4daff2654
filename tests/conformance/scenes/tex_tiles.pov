// tiles { texture .. tile2 texture .. } (seed 003 §5.4.4.1): checker
// cells of whole textures, layered tiles, transformed with the texture.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -7> rgb 1 }
background { rgb <0.5, 0.6, 0.8> }
plane { y, 0
  texture { tiles {
      texture { pigment { rgb <0.9, 0.85, 0.7> } finish { reflection 0.3 } }
      tile2
      texture { pigment { wood scale 0.2 } finish { phong 0.4 } }
    }
    scale 1.2 rotate 30 * y
  }
}
sphere { <0, 1, 0>, 1
  texture { tiles {
      texture { pigment { rgb <1, 1, 0> } }
      texture { pigment { gradient y color_map { [0 rgbt <0, 0, 1, 0.3>] [1 rgbt 1] } scale 0.1 } }
      tile2 texture { pigment { rgb <0.6, 0, 0.8> } finish { phong 0.8 } }
    }
    scale 0.3
  }
}

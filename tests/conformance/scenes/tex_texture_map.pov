// texture_map: the pattern picks one or two textures and povray 3.7
// blends their shaded colours (highlights, reflection and transparency
// included); a declared texture_map; shadows through a mapped texture.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
#declare T_Shiny = texture { pigment { rgb <1, 0.2, 0.1> } finish { phong 0.8 phong_size 40 reflection 0.3 } }
#declare T_Glass = texture { pigment { rgbf <0.6, 1, 0.6, 0.8> } finish { specular 0.6 roughness 0.01 } }
#declare M_Stripes = texture_map {
  [0.3 T_Shiny]
  [0.5 T_Glass]
  [0.7 pigment { rgb <0.2, 0.4, 1> } finish { diffuse 0.9 brilliance 2 }]
}
sphere { <-1.1, 0.9, 0>, 0.9
  texture { gradient y texture_map { M_Stripes } scale 0.6 translate 0.1 * y }
}
sphere { <1.1, 0.9, 0.3>, 0.9
  texture {
    bozo turbulence 0.4 octaves 3
    texture_map {
      [0.4 pigment { rgb <1, 0.9, 0.3> } normal { bumps 0.6 scale 0.1 } finish { phong 0.5 }]
      [0.6 T_Shiny scale 0.5]
    }
    scale 0.5 rotate 30 * y
  }
}
plane { y, 0
  texture { radial frequency 8
    texture_map { [0.5 pigment { rgb 0.9 }] [0.5 pigment { rgb 0.3 } finish { reflection 0.2 }] }
  }
}

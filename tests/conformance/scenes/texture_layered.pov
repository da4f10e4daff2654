// Layered textures (seed 003 5.4.5): a transparent checker lies on a
// shiny red sphere; the floor has a reflective bottom layer under a
// filtering one.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.5, 0> angle 45 }
light_source { <-5, 8, -6> rgb 1 }
background { rgb <0.3, 0.4, 0.7> }
sphere {
  <0, 0.8, 0>, 1
  texture { pigment { rgb <1, 0.1, 0.1> } finish { ambient 0.1 diffuse 0.7 phong 0.6 phong_size 30 } }
  texture {
    pigment { checker rgbt <0.1, 0.9, 0.2, 0.6> rgbt <1, 1, 1, 1> scale 0.4 }
    finish { ambient 0.2 diffuse 0.5 specular 0.4 roughness 0.02 }
  }
}
plane {
  y, -0.2
  texture { pigment { rgb <0.9, 0.8, 0.5> } finish { diffuse 0.6 reflection 0.3 } }
  texture { pigment { gradient x color_map { [0 rgbf <0.2, 0.3, 1, 0.7>] [1 rgbt <1, 1, 1, 0.2>] } } finish { diffuse 0.4 } }
}

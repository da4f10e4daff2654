// Three texture layers: an opaque base, a filtering stripe layer and a
// transmitting spotted top layer, with highlights and a transformation
// after the textures that moves every layer.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 40 }
light_source { <4, 7, -5> rgb 1 }
light_source { <-6, 3, -3> rgb 0.4 }
box {
  <-1, -1, -1>, <1, 1, 1>
  texture { pigment { rgb <0.9, 0.9, 0.2> } finish { ambient 0.15 diffuse 0.6 phong 0.4 } }
  texture { pigment { gradient y color_map { [0.5 rgbf <1, 0.2, 0.2, 0.4>] [0.5 rgbf <0.2, 0.2, 1, 0.8>] } scale 0.5 } finish { diffuse 0.7 } }
  texture { pigment { checker rgbt <1, 1, 1, 0.7> rgbt <0, 0, 0, 0.9> scale 0.3 } finish { ambient 0.05 diffuse 0.3 specular 0.3 } }
  rotate <20, 30, 0>
  translate <0, 0.6, 0>
}
plane { y, -0.8 pigment { checker rgb 1 rgb 0.3 } }

// Conformance: the entries of an average pigment_map, texture_map and
// normal_map may leave their weight out; it is 1 then (povray 3.7; the
// examples qtvr/qtvrpanorama.pov, textures/pigments/txtravg.pov and
// textures/normals/normavg.pov write such maps), mixed with weighted ones.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -7> look_at 0 angle 50 }
light_source { <-3, 4, -6> rgb 1 }
background { rgb 0.15 }
#declare F = finish { ambient 0.3 diffuse 0.7 }
box { <-2.9, 0.15, 0>, <-0.15, 2.6, 1>
  pigment { average pigment_map {
    [gradient y color_map { [0 rgb <1, 0, 0>] [1 rgb <1, 1, 0>] }]
    [3 bozo color_map { [0 rgb <0, 0, 1>] [1 rgb <0, 1, 1>] } scale 0.4]
    [function { x } color_map { [0 rgb 0] [1 rgb 1] }]
  } }
  finish { F }
}
box { <0.15, 0.15, 0>, <2.9, 2.6, 1>
  texture { average texture_map {
    [pigment { rgb <1, 0.5, 0> } finish { F }]
    [2 pigment { radial frequency 8 color_map { [0 rgb 0] [1 rgb <0, 0.5, 1>] } rotate x*90 }
       finish { F phong 1 }]
  } }
}
box { <-2.9, -2.6, 0>, <2.9, -0.15, 1>
  pigment { rgb <0.8, 1, 0.7> }
  normal { average normal_map {
    [gradient x, 1.0 triangle_wave scale 0.5]
    [2 gradient y, -1.0 scallop_wave scale 0.4]
  } }
  finish { F phong 0.6 }
}

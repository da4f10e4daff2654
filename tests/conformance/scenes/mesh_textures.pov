#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
background { color rgb <0.2, 0.25, 0.3> }
// Per-triangle textures; the untextured triangles take the object's.
#declare Red = texture { pigment { color rgb <1, 0.2, 0.1> } }
#declare Check = texture { pigment { checker color rgb 1 color rgb <0, 0, 1> scale 0.2 } }
#declare Apex = <0, 1.2, 0>;
mesh {
  triangle { <-1, 0, -1>, <1, 0, -1>, Apex texture { Red } }
  triangle { <1, 0, -1>, <1, 0, 1>, Apex texture { Check } }
  triangle { <1, 0, 1>, <-1, 0, 1>, Apex }
  triangle { <-1, 0, 1>, <-1, 0, -1>, Apex }
  pigment { color rgb <0.2, 1, 0.3> }
  rotate y * 30
  translate <-1.2, 0, 0>
}
mesh2 {
  vertex_vectors { 5, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, <0, 1.2, 0> }
  texture_list { 3,
    texture { pigment { color rgb <1, 1, 0> } },
    texture { pigment { color rgb <1, 0, 1> } finish { phong 1 } },
    texture { pigment { gradient y color_map { [0 color rgb 0] [1 color rgb 1] } } } }
  face_indices { 4, <0, 1, 4>, 0, <1, 2, 4>, 1, <2, 3, 4>, 2, <3, 0, 4>, 1 }
  rotate y * -20
  translate <1.2, 0, 0>
}
plane { y, 0 pigment { color rgb 0.7 } }

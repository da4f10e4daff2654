#version 3.7;
global_settings { assumed_gamma 1.0 }
// mesh2 with normal_indices (normals shared differently from vertices),
// uv_vectors and uv_indices (read, unused without uv_mapping), a rotated
// copy, and a closed mesh2 with inside_vector in a difference.
camera { location <0, 3, -5.5> look_at <0, 0.2, 0> angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -2> color rgb 0.3 }
background { color rgb <0.2, 0.25, 0.3> }
#declare Tent = mesh2 {
  vertex_vectors { 6, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, <0, 1, -1>, <0, 1, 1> }
  normal_vectors { 3, <-1, 1, 0>, <1, 1, 0>, <0, 1, 0> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  face_indices { 4, <0, 4, 5>, <0, 5, 3>, <1, 2, 5>, <1, 5, 4> }
  normal_indices { 4, <0, 2, 2>, <0, 2, 0>, <1, 1, 2>, <1, 2, 2> }
  uv_indices { 4, <0, 1, 2>, <0, 2, 3>, <0, 1, 2>, <0, 2, 3> }
}
object { Tent translate <-1.3, 0, 0> pigment { color rgb <1, 0.7, 0.3> } finish { phong 0.5 } }
object { Tent rotate y * 50 translate <1.3, 0, 0.3> pigment { color rgb <0.4, 0.8, 1> } }
#declare Tetra = mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0.5, 0, 0.9>, <0.5, 0.8, 0.3> }
  face_indices { 4, <0, 1, 2>, <0, 1, 3>, <1, 2, 3>, <2, 0, 3> }
  inside_vector <0.2, 0.9, 0.1>
}
difference {
  object { Tetra scale 1.6 pigment { color rgb <0.6, 1, 0.5> } }
  sphere { <0.8, 0.3, 0.3>, 0.45 pigment { color rgb <1, 0.3, 0.4> } }
  translate <-0.8, 0, -1.6>
}
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.6 } }

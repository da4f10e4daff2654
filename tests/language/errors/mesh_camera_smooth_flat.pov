// Error test: mesh_camera distribution 3 `smooth` over a flat face. povray
// blends no normals there (its rays run along +x or +y of the mesh,
// whatever the face), so frameray stops rather than rendering another image.
#version 3.7;
#declare M = mesh {
  smooth_triangle { <0, 0, 0>, <0, 0.2, 1>, <0, 1, 0>, <0.2, 0, 1>, <1, 0, 0>, <0, 0, 1> uv_vectors <0, 0>, <0, 1>, <1, 0> }
  triangle { <1, 1, 0>, <1, 0, 0>, <0, 1, 0> uv_vectors <1, 1>, <1, 0>, <0, 1> }
}
camera { mesh_camera { 1 3 mesh { M } smooth } }

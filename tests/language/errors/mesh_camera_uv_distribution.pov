// Error test: mesh_camera's distribution 3 (rays placed by the mesh's uv
// coordinates) is not reproduced yet, so frameray stops rather than
// rendering another image.
#version 3.7;
#declare M = mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> uv_vectors <0, 0>, <1, 0>, <0, 1> } }
camera { mesh_camera { 1 3 mesh { M } } }

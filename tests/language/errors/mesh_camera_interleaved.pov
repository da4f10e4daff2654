// Error test: mesh_camera's distribution 2 (faces taken from the meshes in
// turn) is not reproduced yet, so frameray stops rather than rendering
// another image.
#version 3.7;
#declare M = mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } }
camera { mesh_camera { 1 2 mesh { M } mesh { M translate x } } }

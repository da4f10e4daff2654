#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -9> look_at <0, 0, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
background { color rgb <0.1, 0.1, 0.15> }
// One declared mesh2 (an octahedron with smooth normals) placed many times.
#declare Oct = mesh2 {
  vertex_vectors { 6, <1, 0, 0>, <-1, 0, 0>, <0, 1, 0>, <0, -1, 0>, <0, 0, 1>, <0, 0, -1> }
  normal_vectors { 6, <1, 0, 0>, <-1, 0, 0>, <0, 1, 0>, <0, -1, 0>, <0, 0, 1>, <0, 0, -1> }
  face_indices { 8,
    <0, 2, 4>, <4, 2, 1>, <1, 2, 5>, <5, 2, 0>,
    <0, 4, 3>, <4, 1, 3>, <1, 5, 3>, <5, 0, 3> }
}
#for (I, 0, 4)
  #for (J, 0, 3)
    object { Oct scale 0.6 rotate <I * 17, J * 23, 0> translate <(I - 2) * 1.8, 0, (J - 1.5) * 1.8>
      pigment { color rgb <I / 4, 0.5, J / 3> } finish { phong 0.5 } }
  #end
#end
plane { y, -0.8 pigment { color rgb 0.6 } }

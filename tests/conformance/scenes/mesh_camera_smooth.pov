// Conformance: mesh_camera distribution 3 with `smooth`. A flat sheet of
// 8 x 6 quads of smooth triangles whose corner normals fan out from the
// sheet's centre (a lens): each pixel's ray runs along the corner normals
// blended at its uv point, a perspective view from a coarse mesh. The
// camera's location z moves the starts along those normals.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare NU = 8; #declare NV = 6;
#macro P(I, J) <-3 + 6 * I / NU, -2.25 + 4.5 * J / NV, 0> #end
#macro N(I, J) vnormalize(P(I, J) * <0.25, 0.25, 0> + z) #end
#macro UV(I, J) <I / NU, J / NV> #end
#declare Sheet = mesh {
  #for (J, 0, NV - 1)
    #for (I, 0, NU - 1)
      smooth_triangle { P(I, J), N(I, J), P(I, J + 1), N(I, J + 1), P(I + 1, J), N(I + 1, J)
        uv_vectors UV(I, J), UV(I, J + 1), UV(I + 1, J) }
      smooth_triangle { P(I + 1, J + 1), N(I + 1, J + 1), P(I + 1, J), N(I + 1, J),
        P(I, J + 1), N(I, J + 1) uv_vectors UV(I + 1, J + 1), UV(I + 1, J), UV(I, J + 1) }
    #end
  #end
}
camera {
  mesh_camera { 1 3 mesh { Sheet rotate x * 15 translate <0, 1.5, -6> } smooth }
  location <0, 0, 1>
}
light_source { <-5, 10, -8> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, -1 pigment { checker rgb 0.9 rgb <0.3, 0.5, 0.3> scale 0.5 } }
sphere { <-1.5, 0, 0.5>, 1 pigment { rgb <1, 0.6, 0.2> } finish { phong 0.6 } }
cylinder { <1.5, -1, 0>, <1.5, 1.5, 0>, 0.7 pigment { rgb <0.4, 0.5, 1> } }

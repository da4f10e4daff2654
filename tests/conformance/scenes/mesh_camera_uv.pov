// Conformance: mesh_camera distribution 3. Each pixel is a uv point; the
// ray starts where the camera mesh's uv_vectors put that point (the
// barycentric blend of its face's corners) and runs along the face's
// normal. The mesh is a flat sheet of 8 x 6 quads, fewer faces than
// pixels, whose corners are pushed about in the sheet's plane while
// their uv stay on a regular grid: the view is an orthographic one warped
// piece by piece. The top-left quad has no uv_vectors (black pixels).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare NU = 8; #declare NV = 6;
#macro P(I, J)
  <-3 + 6 * I / NU + 0.25 * sin(J * 1.7 + I), -2.25 + 4.5 * J / NV + 0.2 * cos(I * 1.3), 0>
#end
#macro UV(I, J) <I / NU, J / NV> #end
#declare Sheet = mesh {
  #for (J, 0, NV - 1)
    #for (I, 0, NU - 1)
      #if (I = 0 & J = NV - 1)
        triangle { P(I, J), P(I, J + 1), P(I + 1, J) }
        triangle { P(I + 1, J + 1), P(I + 1, J), P(I, J + 1) }
      #else
        triangle { P(I, J), P(I, J + 1), P(I + 1, J) uv_vectors UV(I, J), UV(I, J + 1), UV(I + 1, J) }
        triangle { P(I + 1, J + 1), P(I + 1, J), P(I, J + 1)
          uv_vectors UV(I + 1, J + 1), UV(I + 1, J), UV(I, J + 1) }
      #end
    #end
  #end
}
camera { mesh_camera { 1 3 mesh { Sheet rotate x * 25 translate <0, 1.5, -6> } } }
light_source { <-5, 10, -8> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, -1 pigment { checker rgb 0.9 rgb <0.3, 0.5, 0.3> scale 0.5 } }
sphere { <-1.5, 0, 0.5>, 1 pigment { rgb <1, 0.6, 0.2> } finish { phong 0.6 } }
cylinder { <1.5, -1, 0>, <1.5, 1.5, 0>, 0.7 pigment { rgb <0.4, 0.5, 1> } }

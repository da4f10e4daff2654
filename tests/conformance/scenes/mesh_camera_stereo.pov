// Conformance: mesh_camera distribution 2, side-by-side cameras. Two grids
// of 80 x 120 faces (one face per pixel of each half of a 160-wide image)
// look at the scene from two places. Mesh k covers the columns
// [k W / 2, (k + 1) W / 2), but povray numbers its face from the image's
// column, not the column inside the half: the right half starts one face
// row down its grid, and its bottom row runs past the last face (black).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare W = 80; #declare H = 120;
#declare S = 4.5 / H;  // face size
#declare Grid = mesh {
  #for (J, 0, H - 1)
    #for (I, 0, W - 1)
      #local X = -1.5 + I * S; #local Y = 2.25 - (J + 2) * S;
      triangle { <X, Y, 0>, <X + S, Y + S, 0>, <X + S, Y, 0> }
    #end
  #end
}
camera {
  mesh_camera { 1 2
    mesh { Grid rotate x * 20 rotate y * 8 translate <-0.6, 1, -6> }
    mesh { Grid rotate x * 20 rotate y * -8 translate <0.6, 1, -6> }
  }
}
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, -1 pigment { checker rgb 0.9 rgb <0.3, 0.5, 0.3> } }
sphere { <-1, 0, 0>, 1 pigment { rgb <1, 0.6, 0.2> } finish { phong 0.6 } }
cylinder { <1.2, -1, 0.5>, <1.2, 1, 0.5>, 0.6 pigment { rgb <0.4, 0.5, 1> } }

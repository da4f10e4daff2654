// Conformance: mesh_camera. A grid of faces, one per pixel, looks at the
// scene like an orthographic camera tilted down; a second copy of the grid
// shifted by half a face is averaged with it (2 rays per pixel,
// distribution 0). Faces are numbered row after row from the top; povray
// gives the top two pixel rows the first row of faces, so the grid starts
// one row down. The camera's location z moves each ray's start along its
// face normal past the thin box in front of the grid.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare W = 160; #declare H = 120;
#declare S = 6 / W;  // face size
#declare Grid = mesh {
  #for (J, 0, H - 1)
    #for (I, 0, W - 1)
      #local X = -3 + I * S; #local Y = 2.25 - (J + 2) * S;
      triangle { <X, Y, 0>, <X + S, Y + S, 0>, <X + S, Y, 0> }
    #end
  #end
}
camera {
  mesh_camera { 2 0
    mesh { Grid rotate x * 20 translate <0, 1, -6> }
    mesh { Grid translate <S / 2, S / 2, 0> rotate x * 20 translate <0, 1, -6> }
  }
  location <0, 0, 0.5>
}
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
// In front of the grid, closer than the rays' start: never seen.
box { <-4, -4, 0.1>, <4, 4, 0.2> pigment { rgb <1, 0, 0> } rotate x * 20 translate <0, 1, -6> }
plane { y, -1 pigment { checker rgb 0.9 rgb <0.3, 0.5, 0.3> } }
sphere { <-1, 0, 0>, 1 pigment { rgb <1, 0.6, 0.2> } finish { phong 0.6 } }
cylinder { <1.2, -1, 0.5>, <1.2, 1, 0.5>, 0.6 pigment { rgb <0.4, 0.5, 1> } }

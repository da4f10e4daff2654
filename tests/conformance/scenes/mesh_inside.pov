#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0, 0> angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
background { color rgb <0.2, 0.25, 0.3> }
// A closed mesh (a cube) with inside_vector takes part in CSG.
#declare Cube = mesh {
  triangle { <-1, -1, -1>, <1, -1, -1>, <1, 1, -1> } triangle { <-1, -1, -1>, <1, 1, -1>, <-1, 1, -1> }
  triangle { <-1, -1, 1>, <1, -1, 1>, <1, 1, 1> } triangle { <-1, -1, 1>, <1, 1, 1>, <-1, 1, 1> }
  triangle { <-1, -1, -1>, <-1, 1, -1>, <-1, 1, 1> } triangle { <-1, -1, -1>, <-1, 1, 1>, <-1, -1, 1> }
  triangle { <1, -1, -1>, <1, 1, -1>, <1, 1, 1> } triangle { <1, -1, -1>, <1, 1, 1>, <1, -1, 1> }
  triangle { <-1, -1, -1>, <1, -1, -1>, <1, -1, 1> } triangle { <-1, -1, -1>, <1, -1, 1>, <-1, -1, 1> }
  triangle { <-1, 1, -1>, <1, 1, -1>, <1, 1, 1> } triangle { <-1, 1, -1>, <1, 1, 1>, <-1, 1, 1> }
  inside_vector <0.3, 0.7, 0.2>
}
difference {
  object { Cube pigment { color rgb <1, 0.7, 0.3> } }
  sphere { <0, 0, 0>, 1.3 pigment { color rgb <0.3, 0.5, 1> } }
  rotate y * 25
  translate <-1.3, 0, 0>
}
intersection {
  object { Cube rotate <20, 30, 0> pigment { color rgb <0.5, 1, 0.5> } }
  sphere { <0, 0, 0>, 1.35 pigment { color rgb <1, 0.3, 0.5> } }
  translate <1.3, 0, 0>
}

// Conformance: an element of an array of pigments or normals opens a
// pigment { } or normal { } block as an identifier does, then modified
// (the example portfolio's pages write `pigment { Pigments[frame_number-1] }`).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -7> look_at 0 angle 50 }
light_source { <-3, 4, -6> rgb 1 }
background { rgb 0.15 }
#declare Pigments = array[3] {
  pigment { checker rgb <1, 0.4, 0.2> rgb 0.9 scale 0.3 },
  pigment { gradient x color_map { [0 rgb <0.2, 0.4, 1>] [1 rgb 1] } },
  pigment { rgb <0.3, 1, 0.4> }
}
#declare Normals = array[2] { normal { bumps 0.6 scale 0.2 }, normal { gradient y, 1 scale 0.3 } }
#declare Nested = array[2] { array[1] { pigment { rgb <1, 1, 0.3> } }, array[1] { pigment { rgb 0.5 } } }
#declare I = 0;
#while (I < 3)
  sphere { <-2.2 + 2.2 * I, 0.9, 0>, 0.9
    pigment { Pigments[I] rotate z*30 }
    normal { Normals[mod(I, 2)] }
    finish { phong 0.5 }
  }
  #declare I = I + 1;
#end
box { <-3, -2.2, 0>, <3, -0.6, 1> pigment { Nested[0][0] } normal { Normals[1] scale 2 } }

// Conformance: list patterns with pigment { } entries where the earlier
// code allowed colours only: the object pattern (its first entry decides
// between colours and pigments, as in the example advanced/abyss.pov) and
// square, triangular and cubic, which povray 3.7 takes pigments in too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -8> look_at 0 angle 50 }
light_source { <-3, 4, -6> rgb 1 }
background { rgb 0.1 }
#declare Bozo = pigment { bozo color_map { [0 rgb <1, 1, 0.2>] [1 rgb <0.2, 0.4, 1>] } scale 0.3 }
box { <-3.5, 0.1, 0>, <-0.1, 3, 1> translate z*0.35
  pigment { object { sphere { <-1.8, 1.5, 0.35>, 1.1 } pigment { rgb <1, 0.3, 0.2> }, pigment { Bozo } } }
}
box { <0.1, 0.1, 0>, <3.5, 3, 1> translate z*0.35
  pigment { square pigment { rgb <1, 0.5, 0> } pigment { Bozo } pigment { rgb 0.2 }
            pigment { checker rgb 1 rgb 0 scale 0.2 } scale 0.7 }
}
box { <-3.5, -3, 0>, <-0.1, -0.1, 1> translate z*0.35
  pigment { triangular pigment { rgb <1, 0, 0> } pigment { rgb <0, 1, 0> } pigment { Bozo }
            pigment { rgb <1, 1, 0> } pigment { rgb <0, 1, 1> } pigment { rgb <1, 0, 1> } scale 0.8 }
}
box { <0.1, -3, 0>, <3.5, -0.1, 1> translate z*0.35
  pigment { cubic pigment { rgb <1, 0.2, 0.2> } pigment { Bozo } pigment { rgb <0.2, 0.2, 1> }
            pigment { rgb 0.9 } pigment { rgb <0.9, 0.9, 0.2> } pigment { rgb <0.2, 0.9, 0.9> }
            rotate <20, 30, 0> }
}

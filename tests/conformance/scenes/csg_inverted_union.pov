// A union used inverted - subtracted in a difference, or given `inverse`
// inside an intersection - keeps only its outer surface: povray inverts
// it into the intersection of its inverted operands, so where its
// operands overlap no inner surface shows through the hole (issue 22,
// qtvrpanorama.pov's hollow boxes).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -5> look_at <0, 0.3, 0> angle 60 }
light_source { <5, 10, -10> rgb 1 }
#declare Pair = union { sphere { <-0.4, 1, 0>, 0.9 } sphere { <0.4, 1, 0>, 0.9 } }
#declare Cross = union {
    cylinder { <0, 0, -1.5>, <0, 0, 1.5>, 0.35 }
    cylinder { <-1.5, 0, 0>, <1.5, 0, 0>, 0.35 }
    cylinder { <0.3, 0, -1.5>, <0.3, 0, 1.5>, 0.35 }
}
difference {
    box { <-1.5, -1, -1.5>, <1.5, 1, 1.5> }
    object { Pair }
    pigment { rgb <1, 0.8, 0.6> }
    translate -1.7 * x
}
intersection {
    box { <-1.2, -0.8, -1.2>, <1.2, 0.8, 1.2> }
    object { Cross inverse translate 0.8 * y }
    pigment { rgb <0.6, 0.8, 1> }
    translate 1.7 * x
}

// Conformance: a linear_spline lathe (a vase with a foot, rim and hollow)
// and a second one rotated onto its side.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
#declare Vase = lathe {
    linear_spline 9,
    <0, -1>, <0.8, -1>, <0.8, -0.8>, <0.3, -0.6>, <0.35, 0.4>, <0.9, 1.2>, <0.8, 1.25>, <0.25, 0.5>, <0, 0.5>
}
object { Vase pigment { color rgb <0.9, 0.3, 0.2> } translate <-1.5, 0, 0> }
object { Vase pigment { color rgb <0.3, 0.4, 0.9> } rotate <0, 0, 70> translate <1.6, 0, 0.5> }

// Conformance: textures in CSG — children without a texture take the
// CSG's; children with one keep it; a declared CSG recoloured by
// object { U pigment { } } recolours only its untextured children; nested
// CSG inherit through levels; finishes per child; flags on a CSG reach
// its children (no_shadow on the union, no_shadow on one child).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -9> look_at <0, 0.5, 0> angle 55 }

light_source { <-4, 10, -7> color rgb <1, 1, 1> }

plane { y, 0 pigment { color rgb <0.75, 0.75, 0.75> } }

#declare U = union {
    sphere { <-0.5, 0.5, 0>, 0.5 }
    box { <0.1, 0, -0.4>, <0.9, 0.8, 0.4> pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.8 } }
    pigment { color rgb <0.9, 0.3, 0.2> }
}

object { U translate <-2.6, 0, 1> }
object { U pigment { color rgb <0.3, 0.4, 0.95> } translate <0, 0, 1> }
object { U finish { ambient 0.4 } translate <2.6, 0, 1> }

// Nested: the inner union has no texture, so its sphere takes the outer one's.
union {
    union { sphere { <-0.4, 0.4, 0>, 0.4 } cylinder { <0.3, 0, 0>, <0.3, 1, 0>, 0.25 pigment { color rgb <1, 1, 0.3> } } }
    box { <-0.8, 0, 0.5>, <0.8, 0.2, 0.9> }
    pigment { color rgb <0.8, 0.4, 0.9> }
    translate <-1.8, 0, -2>
}

// no_shadow on the whole union, and on one child of another.
union { sphere { <0, 1.4, 0>, 0.35 } sphere { <0.6, 1.4, 0>, 0.3 } no_shadow
    pigment { color rgb <0.3, 0.9, 0.9> } translate <0.2, 0, -2> }
union { sphere { <0, 1.4, 0>, 0.35 no_shadow } sphere { <0.7, 1.4, 0>, 0.3 }
    pigment { color rgb <0.95, 0.6, 0.3> } translate <2, 0, -2> }

// Conformance: intersection and difference — a lens, a rounded cube
// (box and sphere), a box with holes drilled by cylinders, a sphere
// bitten by a cone, nested CSG, children with their own pigments and
// transforms and a difference of three operands.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <1, 5, -9> look_at <0, 0.6, 0> angle 55 }

light_source { <-5, 10, -8> color rgb <1, 1, 1> }
light_source { <7, 4, -5> color rgb <0.35, 0.35, 0.35> }

plane { y, 0 pigment { color rgb <0.7, 0.7, 0.65> } }

// Lens.
intersection { sphere { <0, 0, -0.6>, 1 } sphere { <0, 0, 0.6>, 1 }
    rotate y * 60 translate <-3, 0.9, 0> pigment { color rgb <0.9, 0.4, 0.3> } finish { phong 0.5 } }

// Rounded cube: box intersected with a sphere.
intersection { box { -0.8, 0.8 } sphere { 0, 1.05 }
    rotate <0, 25, 0> translate <-0.6, 0.8, 1.2> pigment { color rgb <0.3, 0.7, 0.9> } }

// Box with two holes; the cutters have their own pigments, so the hole
// walls show them.
difference {
    box { <-0.9, 0, -0.9>, <0.9, 1.2, 0.9> }
    cylinder { <0, -1, 0>, <0, 2, 0>, 0.45 pigment { color rgb <1, 1, 0.3> } }
    cylinder { <-2, 0.6, 0>, <2, 0.6, 0>, 0.3 pigment { color rgb <0.3, 1, 0.3> } }
    pigment { color rgb <0.85, 0.85, 0.85> }
    rotate y * -30 translate <2.4, 0, 0.6>
}

// Sphere bitten by a cone.
difference { sphere { 0, 0.8 } cone { <0, 0, -1.5>, 0.9, <0, 0, 0.2>, 0 }
    translate <0.7, 0.8, -1.8> pigment { color rgb <0.8, 0.5, 0.9> } }

// Nested: (box - sphere) intersected with a cylinder, then moved.
intersection {
    difference { box { -0.7, 0.7 } sphere { <0, 0.7, 0>, 0.55 } }
    cylinder { <0, -1, 0>, <0, 1, 0>, 0.8 }
    pigment { color rgb <0.95, 0.7, 0.3> }
    translate <-2.3, 0.7, -2>
}

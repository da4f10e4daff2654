// Conformance: boxes only (plus a floor). Corners are given in both orders
// (the renderer must sort them), some boxes are rotated so three faces and
// their distinct shading are visible. Two white lights of unequal strength
// give two overlapping shadows per box.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <1.5, 4, -7>
    look_at <0, 0.6, 0>
    angle 55
}

light_source { <-6, 9, -4> color rgb <0.8, 0.8, 0.8> }
light_source { <7, 6, -8> color rgb <0.45, 0.45, 0.45> }

plane { y, 0 pigment { color rgb <0.6, 0.65, 0.6> } }

// Axis aligned, corners min/max.
box { <-3, 0, -1>, <-1.5, 1, 0.5> pigment { color rgb <0.85, 0.55, 0.2> } }

// Corners given max-first: same box shape as an ordinary one.
box { <1.0, 2.0, 1.5>, <-0.5, 0, 0> pigment { color rgb <0.3, 0.7, 0.35> } }

// Rotated about y, then lifted onto the floor.
box {
    <-0.6, -0.6, -0.6>, <0.6, 0.6, 0.6>
    rotate y * 35
    translate <2.3, 0.6, -1.2>
    pigment { color rgb <0.35, 0.4, 0.9> }
}

// A flat slab tilted about two axes, floating, shadowing the floor.
box {
    <-0.9, -0.1, -0.5>, <0.9, 0.1, 0.5>
    rotate <20, 0, -15>
    translate <-0.6, 2.4, -1.8>
    pigment { color rgb <0.9, 0.9, 0.85> }
}

// An orthographic camera given neither angle nor right nor up sees as much
// as the perspective camera would at the look_at distance: right and up
// are scaled by |look_at - location| / |direction| (issue 22,
// transmitfx.pov; measured with location -4*z: 1.33*4 units across,
// direction 2*z halves that, no look_at measures to <0,0,1>).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
    orthographic
    location <1, 7, -3>
    direction 1.25 * z
    look_at <0, 0, 0.5>
}
light_source { <4, 10, -6> rgb 1 }
background { rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.85> rgb <0.25, 0.3, 0.35> } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <1.6, 0, -0.5>, <2.6, 1.5, 0.5> pigment { rgb <0.3, 0.8, 0.4> } }
cylinder { <-2.2, 0, 0.5>, <-2.2, 2.2, 0.5>, 0.5 pigment { rgb <0.9, 0.8, 0.2> } }

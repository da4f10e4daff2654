// Conformance: colors.inc names and #declare arithmetic. Every value below
// comes through a declared float, vector or colour, combined with + - * /,
// parentheses, unary minus and the x/y/z built-in vectors.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

#declare Radius = 0.5 + 0.25 * 2;       // 1.0
#declare Gap = (Radius + 0.4) * 2;      // 2.8
#declare Lift = y * Radius;             // <0, 1, 0>
#declare Eye = <0, 3.5, -5> + -z * 2 + x; // <1, 3.5, -7>
#declare Warm = (Orange + Red) / 2;     // colour average
#declare Dim = <1, 1, 1> * 0.35;
#declare LightCol = <1, 0.95, 0.9> - <0, 0.05, 0.1> * 0.5;

camera {
    location Eye
    look_at Lift * 0.8
    angle 56
}

light_source { Eye + <-4, 8, 1> color rgb LightCol }
light_source { <6, 4, -3> color rgb Dim }

plane { y, 0 pigment { color Gray60 } }

sphere { -x * Gap + Lift, Radius pigment { Red } }
sphere { Lift, Radius pigment { color Warm } finish { phong 0.5 } }
sphere { x * Gap + Lift, Radius pigment { color red 1 green 0.5 } }

box {
    <-1, 0, -1> * 0.6, <1, 2, 1> * 0.6
    translate (x * Gap / 2 + z * 2.5)
    pigment { ForestGreen }
}

box {
    -<1, 0, 1> * 0.6, <1, 1, 1> * 0.6
    translate -x * Gap / 2 + 2.5 * z
    pigment { color MediumBlue }
}

// Conformance: tori (closed-form quartic), one tilted, one thin, one with
// r > R (a self-intersecting spindle torus), and a torus in CSG.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 55 }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }

torus { 1.2, 0.35 rotate x * 30 translate <-1.8, 0.5, 0>
    pigment { color rgb <0.9, 0.4, 0.2> } finish { phong 0.5 } }
torus { 1.0, 0.06 rotate z * 70 translate <0.6, 0.4, 1.2> pigment { color rgb <0.3, 0.8, 0.3> } }
torus { 0.5, 0.7 translate <2.3, 0, -0.8> pigment { color rgb <0.3, 0.5, 0.95> } finish { phong 0.3 } }
difference {
    torus { 0.8, 0.3 rotate x * 90 }
    box { <-2, -2, -2>, <0, 2, 2> }
    translate <0, 0.3, -1.8>
    pigment { color rgb <0.9, 0.85, 0.3> }
}

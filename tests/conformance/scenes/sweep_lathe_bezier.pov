// Conformance: a bezier_spline lathe of three pieces (an onion dome) and
// one tilted towards the camera.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
#declare Dome = lathe {
    bezier_spline 12,
    <0, -1>, <0.6, -1>, <1.2, -0.6>, <1, 0>,
    <1, 0>, <0.8, 0.5>, <0.2, 0.6>, <0.15, 1>,
    <0.15, 1>, <0.12, 1.3>, <0.05, 1.5>, <0, 1.6>
}
object { Dome pigment { color rgb <0.8, 0.4, 0.8> } translate <-1.5, 0, 0> }
object { Dome pigment { color rgb <0.3, 0.7, 0.8> } rotate <-50, 0, 0> translate <1.6, 0.3, 0> }

// Conformance: camera identifiers. A declared camera is reused and
// transformed (povray 3.7 accepts only transformations after a camera
// identifier); transformations stack on the declared camera's.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare BaseCamera = camera {
    perspective
    location <0, 2, -6>
    look_at <0, 1, 0>
    angle 75
}
#declare Turned = camera { BaseCamera rotate <0, 25, 0> }

camera { Turned translate <0, 0.5, 0> }

light_source { <4, 10, -6> color rgb <1, 1, 1> }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb <0.9, 0.9, 0.85> color rgb <0.25, 0.3, 0.35> } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <1.6, 0, -0.5>, <2.6, 1.5, 0.5> pigment { color rgb <0.3, 0.8, 0.4> } }
cylinder { <-2.2, 0, 0.5>, <-2.2, 2.2, 0.5>, 0.5 pigment { color rgb <0.9, 0.8, 0.2> } }
sphere { <0, 1, -8>, 1 pigment { color rgb <0.6, 0.3, 0.9> } }
sphere { <-5, 0.7, -3>, 0.7 pigment { color rgb <0.2, 0.7, 0.9> } }
sphere { <5, 0.7, -3>, 0.7 pigment { color rgb <0.9, 0.5, 0.8> } }

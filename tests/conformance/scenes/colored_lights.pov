// Conformance: several coloured point lights. Each object casts one shadow
// per light, and each shadow is tinted by the lights that still reach it.
// The red light is brighter than 1 so the sphere's lit side clips in red (the
// renderer must clamp per channel, not rescale).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0.5, 3.5, -4.5>
    look_at <0, 0.5, 0>
    angle 62
}

light_source { <-5, 6, -3> color rgb <1.3, 0.1, 0.1> }
light_source { <0, 7, -5> color rgb <0.1, 0.7, 0.1> }
light_source { <5, 6, -2> color rgb <0.15, 0.2, 0.8> }

plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.05 diffuse 0.7 } }

sphere { <-1, 1, 0.5>, 1 pigment { color rgb <1, 1, 1> } finish { ambient 0.05 diffuse 0.8 } }

box {
    <1, 0, -0.5>, <2.2, 1.6, 0.7>
    pigment { color rgb <1, 1, 1> }
    finish { ambient 0.05 diffuse 0.8 }
}

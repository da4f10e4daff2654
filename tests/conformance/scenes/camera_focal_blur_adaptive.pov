// Conformance: focal blur sampled as povray samples it. 24 rays at most
// (the 19-point hexagonal grid, then 5 Halton points on the aperture disc),
// at least 4, default confidence and variance, so the number of rays
// varies from pixel to pixel (povray's stopping test); the focal point is
// off the view axis (its distance from the eye sets the sharp plane); and
// anti-aliasing (+A0.3 in the manifest) traces blurred sub-pixel samples.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 2, -7>
    look_at <0, 1, 0>
    angle 45
    aperture 0.5
    blur_samples 4, 24
    focal_point <-1.5, 1, -1>
}

light_source { <-5, 9, -8> color rgb <1, 1, 1> }
background { color rgb <0.35, 0.5, 0.75> }
plane { y, 0 pigment { checker color rgb <0.95, 0.9, 0.8> color rgb <0.2, 0.25, 0.3> scale 0.75 } }
sphere { <-1.5, 1, -1>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
box { <0.6, 0, 1>, <1.8, 2.2, 2.2> rotate y*25 pigment { checker color rgb <0.2, 0.6, 0.9> color rgb 1 scale 0.4 } }
sphere { <3, 0.8, 6>, 0.8 pigment { color rgb <0.3, 0.85, 0.35> } }
cylinder { <-3.5, 0, 5>, <-3.5, 3, 5>, 0.3 pigment { color rgb <0.9, 0.8, 0.2> } }

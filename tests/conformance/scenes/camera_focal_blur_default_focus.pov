// Conformance: focal blur without focal_point (povray then focuses at the
// direction vector's length, here 2.5 units: the near sphere is sharp) and
// with 5 rays (povray's 2 x 2 square grid plus one Halton point, jittered
// by 0.5 / sqrt(5)); default confidence and variance.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 1, -4>
    direction <0, 0, 2.5>
    look_at <0, 1, 0>
    aperture 0.4
    blur_samples 5
}

light_source { <4, 8, -6> color rgb <1, 1, 1> }
background { color rgb <0.3, 0.45, 0.7> }
plane { y, 0 pigment { checker color rgb <0.9, 0.9, 0.85> color rgb <0.25, 0.3, 0.35> scale 0.5 } }
sphere { <0.3, 0.9, -1.5>, 0.5 pigment { color rgb <0.95, 0.4, 0.2> } finish { phong 0.5 } }
sphere { <-1.4, 1, 2>, 1 pigment { checker color rgb <0.2, 0.5, 0.9> color rgb 1 scale 0.3 } }

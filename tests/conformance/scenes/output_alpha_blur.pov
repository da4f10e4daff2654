// Output_Alpha (+UA) with focal blur: transmittance is averaged over the
// aperture rays with the colour, so the blurred edges of objects against
// the clear sky (a 3.7 scene without background) turn partly transparent.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
    location <0, 1.5, -6>
    look_at <0, 1, 0>
    angle 50
    aperture 0.6
    blur_samples 37
    focal_point <0, 1, 0>
    confidence 0.9
    variance 0  // never stop early: all 37 rays, the least noise
}
light_source { <4, 10, -6> color rgb <1, 1, 1> }
sphere { <-2.2, 0.7, -3>, 0.7 pigment { color rgb <0.2, 0.7, 0.9> } }
sphere { <0, 1, 0>, 1 pigment { color rgbt <0.9, 0.3, 0.2, 0.3> } finish { phong 0.6 } }
sphere { <2.8, 1, 4>, 1 pigment { color rgb <0.3, 0.8, 0.4> } }

// Conformance: focal blur. Spheres at increasing depth; the middle one is
// at the focal point and stays sharp, the others blur with distance from
// the focal plane.
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
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb <0.9, 0.9, 0.85> color rgb <0.25, 0.3, 0.35> } }
sphere { <-2.2, 0.7, -3>, 0.7 pigment { color rgb <0.2, 0.7, 0.9> } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <2.8, 1, 4>, 1 pigment { color rgb <0.3, 0.8, 0.4> } }

// Conformance: focal blur with an orthographic camera. povray 3.7 starts
// every blurred ray at the camera's location (moved across the aperture)
// with the view direction, dropping the orthographic per-pixel offset: the
// image is a blurred view of whatever lies straight ahead of the location.
// frameray reproduces that.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
    orthographic
    location <0, 1.5, -6>
    look_at <0, 1, 0>
    aperture 1.5
    blur_samples 7
    focal_point <0, 1, 0>
}
light_source { <4, 10, -6> color rgb 1 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.2 scale 0.25 } }
sphere { <0.3, 1.2, 0>, 0.6 pigment { checker color rgb <0.9, 0.3, 0.2> color rgb 1 scale 0.1 } }

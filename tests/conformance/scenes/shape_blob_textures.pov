// Conformance: textures on blob components (issue 9). povray 3.7 shades
// each component's texture and blends the colours by the components'
// shares |field_i| / sum |field_j| at the point; untextured components
// take the blob's texture; a transformation after a component's texture
// moves it; a negative component's texture shows where it dents the blob.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.4, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 4, -2> color rgb 0.3 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
blob {
    threshold 0.6
    sphere { <-1, 0, 0>, 1.2, 1 texture { pigment { color rgb <0.9, 0.2, 0.1> } finish { phong 0.5 } } }
    sphere { <0, 0, 0>, 1.2, 1 pigment { checker color rgb <0.1, 0.3, 0.9> color rgb 1 scale 0.3 } scale <1, 1.3, 1> }
    sphere { <1, 0, 0>, 1.2, 1 }
    cylinder { <-1, 0, 0>, <1, 0, 0>, 0.5, 1 texture { pigment { color rgb <1, 0.9, 0.1> } } translate 0.4*y }
    sphere { <0.5, 0.4, -1.1>, 0.9, -1.5 texture { pigment { color rgb <0.1, 0.9, 0.9> } } }
    texture { pigment { color rgb <0.3, 0.8, 0.3> } finish { specular 0.4 } }
    rotate 20*y
    translate <-0.3, 0, 0.5>
}
blob {
    threshold 0.5
    component 1, 1, <0, 0, 0>
    sphere { <0.8, 0.2, 0>, 0.9, 1.5 texture { pigment { gradient y color_map { [0 color rgb <1, 0.5, 0>] [1 color rgb <0.5, 0, 1>] } } } }
    scale 0.7
    translate <1.9, -0.3, -2.2>
}

// Conformance: a parametric surface inside CSG and with a texture (issue
// 9). povray's parametric reports only the first crossing along a ray and
// encloses nothing (its inside test is false, inverted or not), so an
// intersection with a box keeps only the band of the surface inside the
// box and none of the box; clipped_by keeps the near half only.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -3> color rgb 0.4 }
plane { y, -1.2 pigment { checker color rgb 0.8 color rgb 0.55 } }
#declare Wave = parametric {
    function { u }
    function { 0.3*sin(3*u)*cos(2*v) }
    function { v }
    <-1.5, -1.5>, <1.5, 1.5>
    contained_by { box { <-1.5, -0.5, -1.5>, <1.5, 0.5, 1.5> } }
    max_gradient 1.2
}
object {
    Wave
    texture {
        pigment { gradient x color_map { [0 color rgb <0.9, 0.2, 0.2>] [1 color rgb <0.2, 0.3, 0.9>] } scale 3 translate -1.5*x }
        normal { bumps 0.2 scale 0.3 }
        finish { specular 0.5 roughness 0.02 }
    }
    translate <-1.2, 0, 0.8>
}
#declare Ball = parametric {
    function { cos(u)*sin(v) }
    function { cos(v) }
    function { sin(u)*sin(v) }
    <0, 0>, <2*pi, pi>
    contained_by { sphere { 0, 1.01 } }
    pigment { color rgb <1, 0.7, 0.2> }
}
intersection {
    box { <-1.5, -0.3, -1.5>, <1.5, 0.3, 1.5> pigment { color rgb <0.3, 0.9, 0.3> } }
    object { Ball }
    translate <1.6, 0, -0.5>
}
object {
    Ball
    clipped_by { plane { z, 0 } }
    pigment { color rgb <0.6, 0.4, 0.9> }
    scale 0.7
    translate <1.6, 0.2, 1.6>
}

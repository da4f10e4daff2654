// Conformance: parametric surfaces (issue 9): a torus in a box container
// with a checker in space and the default max_gradient 1, well below its
// true gradient 1.6 (povray still finds all of it: it bounds pieces of
// the surface by sampled points, not by max_gradient alone), a sphere in a sphere container with precompute,
// and a twisted ribbon (an open surface, seen from both sides) rotated
// and scaled, with a declared function called from the bodies.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
#declare R = 1.25;
#declare r = 0.35;
parametric {
    function { (R + r*cos(v))*cos(u) }
    function { r*sin(v) }
    function { (R + r*cos(v))*sin(u) }
    <0, 0>, <2*pi, 2*pi>
    contained_by { box { <-1.65, -0.4, -1.65>, <1.65, 0.4, 1.65> } }
    pigment { checker color rgb <0.9, 0.3, 0.2> color rgb <1, 0.9, 0.6> scale 0.25 }
    rotate 30*x
    translate <-2.1, -0.2, 0.8>
}
parametric {
    function { cos(u)*sin(v) }
    function { cos(v) }
    function { sin(u)*sin(v) }
    <0, 0>, <2*pi, pi>
    contained_by { sphere { 0, 1.01 } }
    precompute 12, x, y, z
    pigment { color rgb <0.2, 0.5, 0.9> }
    finish { phong 0.6 }
    scale 0.8
    translate <0.3, -0.2, -1.2>
}
#declare Half = function(a) { 0.5*a }
parametric {
    function { u*cos(Half(v)) }
    function { v/pi*0.6 }
    function { u*sin(Half(v)) }
    <-0.6, 0>, <0.6, 2*pi>
    contained_by { box { -1, 1 } }
    max_gradient 1.2
    accuracy 0.0005
    pigment { color rgb <0.3, 0.8, 0.3> }
    rotate -20*y
    translate <2, -0.4, 0.8>
}

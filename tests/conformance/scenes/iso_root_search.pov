// povray's isosurface root search, step for step: it halves the ray's part
// in the container while max_gradient leaves room for a root and returns
// the far end of the last interval shorter than `accuracy` (not the root),
// and its normal is a forward difference over `accuracy`. With a coarse
// accuracy the hit points lie visibly beyond the surface: the fine stripes
// show where each ray stopped, the lights show the normals.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0, 0> angle 45 }
light_source { <-10, 12, -8> color rgb 1 }
light_source { <12, 3, -4> color rgb <0.4, 0.5, 0.7> }
isosurface {
    function { y - 0.4 * sin(2 * x) * cos(3 * z) }
    contained_by { box { <-4, -1, -2>, <4, 1, 3> } }
    accuracy 0.05
    max_gradient 3
    pigment { gradient x color_map { [0 rgb <1, 0.8, 0.3>] [0.5 rgb <1, 0.8, 0.3>] [0.5 rgb <0.2, 0.3, 0.8>] [1 rgb <0.2, 0.3, 0.8>] } scale 0.1 }
    finish { phong 0.4 }
}
isosurface {
    function { x * x + y * y + z * z - 1 + 0.15 * sin(6 * x) * sin(6 * y) }
    contained_by { sphere { 0, 1.6 } }
    accuracy 0.03
    max_gradient 8
    pigment { gradient y color_map { [0 rgb 1] [0.5 rgb 1] [0.5 rgb <0.8, 0.1, 0.1>] [1 rgb <0.8, 0.1, 0.1>] } scale 0.08 }
    finish { phong 0.6 }
    scale <1, 0.8, 1> rotate y * 20 translate <0.5, 1.4, 0.5>
}

// Conformance: cylinders and cones — closed and open, along the axes and
// slanted, pointed and truncated cones, a cone with equal radii (a
// cylinder), all casting shadows on the floor and on each other.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4.5, -9> look_at <0, 0.8, 0> angle 55 }

light_source { <-6, 10, -7> color rgb <0.9, 0.9, 0.9> }
light_source { <8, 6, -4> color rgb <0.35, 0.35, 0.4> }

plane { y, 0 pigment { color rgb <0.7, 0.7, 0.65> } }

// Upright closed cylinder.
cylinder { <-3, 0, 0.5>, <-3, 2, 0.5>, 0.7 pigment { color rgb <0.9, 0.3, 0.2> } }
// Open cylinder lying on its side: the inside is visible through the ends.
cylinder { <-1.6, 0.5, -1.8>, <-0.2, 0.5, -0.8>, 0.5 open
    pigment { color rgb <0.3, 0.8, 0.4> } finish { phong 0.6 } }
// Slanted closed cylinder resting above the floor.
cylinder { <0, 0.4, 1.5>, <1.5, 2.2, 2.5>, 0.35 pigment { color rgb <0.3, 0.4, 0.9> } }
// Pointed cone.
cone { <2.2, 0, -0.5>, 0.9, <2.2, 2.2, -0.5>, 0 pigment { color rgb <0.95, 0.8, 0.2> } }
// Truncated cone, wide end up.
cone { <0.5, 0, -2.2>, 0.2, <0.5, 1.3, -2.2>, 0.6 pigment { color rgb <0.8, 0.4, 0.85> } finish { specular 0.5 } }
// Open truncated cone on its side.
cone { <3.2, 0.6, -2.6>, 0.55, <4.2, 0.6, -1.8>, 0.25 open pigment { color rgb <0.2, 0.8, 0.8> } }
// Equal radii: povray makes it a cylinder.
cone { <-3.5, 0, -2.5>, 0.4, <-3.5, 0.8, -2.5>, 0.4 pigment { color rgb <0.6, 0.6, 0.6> } }

// Conformance: quadrics of several kinds, clipped by a box or intersected
// with one — circular cylinder, double cone, hyperboloids, a saddle, an
// ellipsoid with mixed terms, a rotated elliptic cylinder, and a bare
// ellipsoid quadric. (Paraboloids are left out: povray's bounding box for
// them is too small and cuts them, which frameray does not copy.)
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -10> look_at <0, 0, 0> angle 60 }

light_source { <5, 10, -10> color rgb <1, 1, 1> }
light_source { <-8, 3, -6> color rgb <0.3, 0.3, 0.3> }

plane { y, -2.4 pigment { color rgb <0.7, 0.7, 0.7> } }

#declare C = box { -1, 1 }
quadric { <1, 1, 0>, 0, 0, -0.5 clipped_by { object { C } } translate <-3, 1.3, 0> pigment { color rgb <1, 0.2, 0.2> } }
quadric { <1, -1, 1>, 0, 0, 0 clipped_by { object { C } } translate <0, 1.3, 0> pigment { color rgb <0.2, 0.8, 0.3> } }
quadric { <1, -1, 1>, 0, 0, -0.3 clipped_by { object { C } } translate <3, 1.3, 0> pigment { color rgb <0.3, 0.4, 1> } }
quadric { <1, 0, -1>, 0, <0, -1, 0>, 0 clipped_by { object { C } } translate <-3, -1.3, 0> pigment { color rgb <1, 0.8, 0.2> } }
intersection { quadric { <1, 2, 1>, <1, 0, 0.5>, 0, -0.8 } box { -1, 1 } translate <0, -1.3, 0> pigment { color rgb <0.8, 0.3, 0.9> } }
intersection { quadric { <1, 1, 0>, 0, 0, -0.5 } box { -1, 1 } rotate <0, 30, 40> translate <3, -1.3, 0> pigment { color rgb <0.2, 0.8, 0.8> } }
// An ellipsoid needs no clip: (x/0.6)^2 + (y/0.3)^2 + (z/0.4)^2 = 1 with its centre moved.
quadric { <1/0.36, 1/0.09, 1/0.16>, 0, <0, 0, 0>, -1 translate <4.6, 0, -2> pigment { color rgb <0.9, 0.9, 0.9> } }

// Conformance: clipped_by and bounded_by — a sphere clipped by a plane
// (open bowl, its inside visible), a cylinder clipped by a sphere, a box
// clipped by an inverse sphere, clipped_by { bounded_by }, a sphere with
// an undersized bounded_by box (povray skips rays that miss the bound:
// the sphere's edges are cut away), bounded_by { clipped_by }, and a
// clipped CSG.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -9> look_at <0, 0.5, 0> angle 55 }

light_source { <-5, 10, -8> color rgb <1, 1, 1> }
light_source { <6, 4, -6> color rgb <0.3, 0.3, 0.3> }

plane { y, -1 pigment { color rgb <0.7, 0.7, 0.7> } }

sphere { 0, 1 clipped_by { plane { y, 0.3 } } rotate x * -30 translate <-3, 0.2, 0.5>
    pigment { color rgb <0.9, 0.4, 0.2> } }

cylinder { <0, -1, 0>, <0, 1, 0>, 0.7 clipped_by { sphere { <0, 0.3, 0>, 1 } } translate <-1, 0, 1.2>
    pigment { color rgb <0.3, 0.8, 0.4> } }

box { -0.8, 0.8 clipped_by { sphere { <0.8, 0.8, -0.8>, 0.9 inverse } } translate <1.2, 0, 1.2>
    pigment { color rgb <0.3, 0.4, 0.95> } }

sphere { 0, 0.9 bounded_by { box { <-1, -1, -1>, <1, 0.2, 1> } } clipped_by { bounded_by }
    translate <3.3, 0, 0.3> pigment { color rgb <0.9, 0.8, 0.3> } }

sphere { 0, 0.9 bounded_by { box { -0.6, 0.6 } } translate <-1.8, 0, -2>
    pigment { color rgb <0.8, 0.4, 0.9> } }

cylinder { <-1, 0, 0>, <1, 0, 0>, 0.6 clipped_by { box { <-0.8, -1, -1>, <0.8, 0.3, 1> } } bounded_by { clipped_by }
    translate <0.6, 0, -2.2> pigment { color rgb <0.4, 0.9, 0.9> } }

union { sphere { <-0.4, 0, 0>, 0.6 } sphere { <0.4, 0, 0>, 0.6 }
    clipped_by { plane { -z, 0 } }
    translate <2.8, 0, -2> pigment { color rgb <0.95, 0.6, 0.6> } }

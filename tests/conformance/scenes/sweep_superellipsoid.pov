// Conformance: superellipsoids from rounded boxes to pinched stars, one
// rotated, under a point light with shadows on the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }
superellipsoid { <0.25, 0.25> pigment { color rgb <0.9, 0.3, 0.2> } translate <-2.4, 0, 0> }
superellipsoid { <1, 0.3> pigment { color rgb <0.2, 0.7, 0.3> } rotate <-90, 0, 0> rotate <0, 30, 0> }
superellipsoid { <2.5, 2.5> pigment { color rgb <0.3, 0.4, 0.9> } scale 0.9 translate <2.4, 0.2, 0.5> }
superellipsoid { <0.6, 1.6> pigment { color rgb <0.9, 0.8, 0.2> } scale 0.6 translate <-0.8, 1.9, 1.5> }

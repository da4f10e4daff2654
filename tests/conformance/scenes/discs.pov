// Conformance: discs — plain, with a hole, tilted, scaled — and
// double_illuminate: of the two upper discs, lit from the front by one
// light and from behind by another, only the right one also gets the
// light behind it.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }

light_source { <-5, 8, -6> color rgb <0.7, 0.7, 0.7> }
light_source { <0, 3, 8> color rgb <0.6, 0.6, 0.6> }

plane { y, 0 pigment { color rgb <0.6, 0.65, 0.7> } }

disc { <-2.5, 0.01, -1>, y, 1.2 pigment { color rgb <0.9, 0.3, 0.2> } }
disc { <0, 1.2, 0>, <0, 0.3, -1>, 1, 0.45 pigment { color rgb <0.3, 0.8, 0.3> } finish { phong 0.5 } }
disc { <2.6, 1.3, 0.5>, <-1, 0.5, -0.4>, 0.9 scale <1, 1.4, 1> pigment { color rgb <0.3, 0.4, 0.95> } }
disc { <-1.3, 2.6, 1.5>, <0.3, 0, -1>, 0.6 pigment { color rgb <1, 0.8, 0.2> } }
disc { <1.3, 2.6, 1.5>, <-0.3, 0, -1>, 0.6 pigment { color rgb <1, 0.8, 0.2> } double_illuminate }

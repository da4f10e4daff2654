// Conformance: shadows through transparent surfaces: filter tints the
// light by the pigment colour, transmit passes it unchanged; every surface
// crossed counts (a sphere's near and far side); opaque hits stop it.
// The casters are no_image: only their shadows are compared here (seeing
// through them is the tracer's transparency, tested elsewhere).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -7> look_at <0, 0.5, 0> angle 60 }
light_source { <-1, 8, -3> color rgb 1 }
light_source { <5, 5, -1> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-2, 1, 0>, 0.9 pigment { rgbf <1, 0.3, 0.2, 0.8> } finish { ambient 0.05 diffuse 0.3 } no_image }
sphere { <0.3, 1, 0.5>, 0.9 pigment { rgbt <0.2, 0.4, 1, 0.6> } finish { ambient 0.05 diffuse 0.3 } no_image }
box { <1.8, 0, -1>, <2.8, 1.6, 0> pigment { rgbft <0.3, 1, 0.3, 0.5, 0.3> } no_image }
box { <-0.8, 0, -2.2>, <0.2, 0.6, -1.6> pigment { checker rgbf <1, 1, 0, 0.9> rgb 0.5 scale 0.25 } no_image }

// Conformance: a background with filter and transmit behind objects. In
// 3.7 the background is a last sky layer: transmit darkens its colour even
// without an alpha channel, filter does not.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
background { rgbft <0.3, 0.6, 0.95, 0.3, 0.35> }
sphere { <-1.2, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.2> } }
box { <0.4, 0, -0.5>, <2, 1.6, 0.5> pigment { rgb <0.3, 0.8, 0.4> } }

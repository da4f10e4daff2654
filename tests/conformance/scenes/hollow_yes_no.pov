// Conformance: `hollow yes` / `hollow no` (the boolean keywords, as the
// example interior/media/hollow1.pov writes them) inside fog: the hollow
// sphere fills with fog and darkens what is seen through it, the solid one
// does not.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5.5> look_at <0, 0.8, 0> angle 70 }
light_source { <3, 8, -6> rgb 1 }
background { rgb <0.1, 0.1, 0.3> }
fog { distance 5 rgb <0.1, 0.1, 0.3> }
plane { y, -0.5 pigment { checker rgb 1 rgb 0.6 } }
sphere { <-1.8, 1, 0>, 1.6 pigment { rgbt <1, 1, 1, 0.9> } hollow no }
sphere { <1.8, 1, 0>, 1.6 pigment { rgbt <1, 1, 1, 0.9> } hollow yes }

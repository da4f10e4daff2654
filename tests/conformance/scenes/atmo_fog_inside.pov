// Fog along rays inside objects: povray leaves it out, so a deep
// transmitting box and a glass sphere show the fog only in front of and
// beyond them.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2, -9> look_at <0, 1, 0> angle 45 }
light_source { <-8, 12, -10> rgb 1 }
fog { distance 6 rgb <0.5, 0.6, 0.7> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.2 } }
box { <-3.2, 0.2, -1>, <-0.8, 2.5, 5> pigment { rgbt <1, 0.8, 0.6, 0.7> } }
sphere { <1.8, 1.2, 0>, 1.2 pigment { rgbf <0.8, 0.9, 1, 0.9> } interior { ior 1.4 } }

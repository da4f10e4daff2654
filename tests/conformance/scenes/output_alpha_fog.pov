// Output_Alpha (+UA) with fog: each stretch of fog outside objects covers
// what lies behind it and passes on its transmittance (a fog with
// transmit leaves the far sky partly clear); transparent objects let it
// through.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2.5, -8> look_at <0, 0.9, 0> angle 45 }
light_source { <-8, 12, -10> rgb 1 }
fog { distance 12 rgbt <0.7, 0.75, 0.8, 0.4> }
disc { <0, 0, 0>, y, 3.2 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { <-2, 1, 0>, 1 pigment { rgbt <0.9, 0.4, 0.3, 0.6> } }
sphere { <0.3, 1, 1>, 1 pigment { rgbf <0.3, 0.8, 0.5, 0.8> } interior { ior 1.3 } }
box { <1.5, 0.1, -0.5>, <3, 1.5, 3> pigment { rgbt <1, 1, 0.6, 0.8> } }

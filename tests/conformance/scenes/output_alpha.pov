// Output_Alpha (+UA) in a 3.7 scene without background: the sky is clear
// black wherever it is seen straight or through surfaces; transmit and
// filter (by the pigment's grey) let it through in part; mirrors show
// black; PNG holds the colour un-premultiplied.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2.5, -8> look_at <0, 0.9, 0> angle 45 }
light_source { <-8, 12, -10> rgb 1 }
disc { <0, 0, 0>, y, 3.2 pigment { checker rgb 0.8 rgb 0.3 } finish { reflection 0.2 } }
sphere { <-2.2, 1, 0>, 1 pigment { rgbt <0.9, 0.4, 0.3, 0.6> } }
sphere { <0, 1, 0>, 1 pigment { rgbf <0.3, 0.8, 0.5, 0.8> } finish { phong 0.6 } interior { ior 1.3 } }
sphere { <2.2, 1, 0>, 1 pigment { rgb 0.9 } finish { ambient 0 diffuse 0.2 reflection 0.8 } }
box { <-0.5, 2.3, -0.5>, <0.5, 2.6, 0.5> pigment { rgbft <1, 0.9, 0.2, 0.3, 0.4> } rotate y * 30 }

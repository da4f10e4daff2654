// Conformance: fog colours with filter (tints what is behind) and
// transmit (a floor on how much of it stays visible).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1, 4> angle 60 }
light_source { <-5, 10, -8> color rgb 1 }
background { rgb <0.9, 0.9, 0.9> }
plane { y, 0 pigment { checker rgb 1 rgb <0.1, 0.1, 0.4> } }
#declare I = 0;
#while (I < 6)
  sphere { <-1.5, 1, I * 4>, 1 pigment { rgb <1, 0.9, 0.2> } }
  sphere { <1.5, 1, I * 4 + 2>, 1 pigment { rgb <0.9, 0.2, 0.9> } }
  #declare I = I + 1;
#end
fog { distance 8 color rgbft <0.2, 0.6, 1.0, 0.5, 0.25> }

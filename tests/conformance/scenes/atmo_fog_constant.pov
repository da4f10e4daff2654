// Conformance: constant fog over a receding floor and columns; the sky
// (nothing hit) takes the fog colour.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1, 4> angle 60 }
light_source { <-5, 10, -8> color rgb 1 }
background { rgb <0.1, 0.2, 0.6> }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.2, 0.3, 0.2> } }
#declare I = 0;
#while (I < 6)
  cylinder { <-2, 0, I * 4>, <-2, 3, I * 4>, 0.5 pigment { rgb <0.8, 0.3, 0.2> } }
  sphere { <2, 1, I * 4 + 2>, 1 pigment { rgb <0.2, 0.4, 0.9> } }
  #declare I = I + 1;
#end
fog { distance 12 color rgb <0.7, 0.75, 0.8> }

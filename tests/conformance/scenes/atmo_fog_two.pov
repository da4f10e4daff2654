// Conformance: two fogs at once, a thin constant fog and a ground fog
// whose up vector is scaled and turned by a transform block.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -8> look_at <0, 1.5, 4> angle 60 }
light_source { <-5, 10, -8> color rgb 1 }
background { rgb <0.1, 0.1, 0.3> }
plane { y, 0 pigment { checker rgb <0.7, 0.7, 0.6> rgb <0.2, 0.2, 0.25> scale 1.5 } }
#declare I = 0;
#while (I < 6)
  cylinder { <-3, 0, I * 5>, <-3, 5, I * 5>, 0.6 pigment { rgb <0.9, 0.8, 0.3> } }
  cylinder { <3, 0, I * 5 + 2.5>, <3, 5, I * 5 + 2.5>, 0.6 pigment { rgb <0.3, 0.8, 0.9> } }
  #declare I = I + 1;
#end
fog { distance 40 color rgb <0.9, 0.3, 0.2> }
fog { fog_type 2 distance 3 color rgbf <0.6, 0.8, 1.0, 0.3> fog_offset 0.5 fog_alt 1.5
      transform { scale <1, 2, 1> rotate x * -8 } }

// Conformance: ground fog (fog_type 2) with fog_offset and fog_alt, its up
// vector tilted by a rotation, thinning with height.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -10> look_at <0, 1.5, 5> angle 60 }
light_source { <-5, 12, -8> color rgb 1 }
background { rgb <0.2, 0.4, 0.8> }
plane { y, 0 pigment { checker rgb <0.8, 0.8, 0.7> rgb <0.3, 0.25, 0.2> scale 2 } }
#declare I = 0;
#while (I < 5)
  box { <-1, 0, -1>, <1, 6, 1> translate <-4, 0, I * 6> pigment { rgb <0.9, 0.5, 0.2> } }
  box { <-1, 0, -1>, <1, 4, 1> translate <4, 0, I * 6 + 3> pigment { rgb <0.3, 0.7, 0.4> } }
  #declare I = I + 1;
#end
fog {
  fog_type 2
  distance 6
  color rgb <0.85, 0.85, 0.9>
  fog_offset 1.2
  fog_alt 0.8
  up <0, 1, 0>
  rotate z * 10
}

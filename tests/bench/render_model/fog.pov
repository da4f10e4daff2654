// Fog: constant fog plus a ground fog over a long checker plane and pillars.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -10> look_at <0, 1, 0> angle 50 }
light_source { <-10, 20, -15> rgb 1 }
background { rgb <0.5, 0.6, 0.8> }
fog { distance 30 rgb <0.7, 0.75, 0.8> }
fog { fog_type 2 distance 4 fog_offset 0.5 fog_alt 0.4 rgb <0.9, 0.9, 0.95> }
plane { y, 0 pigment { checker rgb 0.9 rgb <0.3, 0.4, 0.3> } }
#for (i, 0, 15)
  cylinder { <-3, 0, i * 3>, <-3, 3, i * 3>, 0.3 pigment { rgb <0.8, 0.5, 0.3> } }
  cylinder { <3, 0, i * 3>, <3, 3, i * 3>, 0.3 pigment { rgb <0.3, 0.5, 0.8> } }
#end

// Declared normals: used alone, with further modifiers, and as
// normal_map entries.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
#declare N_Dents = normal { dents 0.8 scale 0.15 }
#declare N_Waves = normal { waves 0.4 scale 0.3 }
#declare NM = normal_map { [0.3 N_Dents] [0.7 N_Waves] }
sphere { <-1.1, 0.9, 0>, 0.9
  pigment { rgb <1, 0.8, 0.6> } finish { phong 0.6 }
  normal { gradient y normal_map { NM } scale 0.5 }
}
sphere { <1.1, 0.9, 0.3>, 0.9
  pigment { rgb <0.6, 0.8, 1> } finish { specular 0.5 }
  normal { N_Dents bump_size 0.3 scale 2 }
}
plane { y, 0 pigment { rgb 0.8 } normal { N_Dents } }

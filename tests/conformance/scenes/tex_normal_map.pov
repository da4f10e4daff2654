// normal_map: the pattern picks one or two normals and their perturbed
// normals are blended; a list pattern's normals; average; bump_size and
// transformations with maps.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
#declare NM = normal_map { [0.3 bumps 0.8 scale 0.1] [0.7 waves 1 scale 0.2] }
sphere { <-1.1, 0.9, 0>, 0.9
  pigment { rgb <1, 0.8, 0.6> } finish { phong 0.6 }
  normal { gradient y normal_map { NM } scale 0.7 rotate 20 * z }
}
sphere { <1.1, 0.9, 0.3>, 0.9
  pigment { rgb <0.6, 0.8, 1> } finish { specular 0.5 }
  normal { checker normal { dents 0.8 scale 0.1 } normal { ripples 0.6 scale 0.3 } scale 0.4 }
}
plane { y, 0
  pigment { rgb 0.8 }
  normal { average normal_map { [1 wrinkles 0.6 scale 0.3] [2 gradient x 0.5 scale 0.5] } }
}

// Conformance: a normal pattern's bump size may follow it after a comma
// (`gradient x, 5.6`, `pigment_pattern { ... }, 0.5`, and in a normal_map
// entry), as povray 3.7 reads the example textures/patterns/gradient.pov.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -7> look_at 0 angle 45 }
light_source { <-4, 6, -8> rgb 1 }
background { rgb 0.1 }
#declare Fin = finish { phong 0.8 phong_size 60 }
box { <-2.6, 0.1, 0>, <-0.1, 2.4, 1>
  pigment { rgb <1, 0.8, 0.5> } normal { gradient x, 0.8 scale 0.5 } finish { Fin } }
box { <0.1, 0.1, 0>, <2.6, 2.4, 1>
  pigment { rgb <0.6, 0.8, 1> }
  normal { pigment_pattern { checker rgb 1 rgb 0 scale 0.4 }, 0.7 } finish { Fin } }
box { <-2.6, -2.4, 0>, <2.6, -0.1, 1>
  pigment { rgb <0.8, 1, 0.6> }
  normal {
    average
    normal_map { [gradient x, 1.0 triangle_wave scale 0.4] [gradient y, -1.0 scale 0.3] }
  }
  finish { Fin }
}

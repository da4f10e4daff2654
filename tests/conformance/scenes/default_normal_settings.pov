// #default { normal { bump_size B } } names no pattern, yet every normal
// written afterwards starts from it: normal { gradient x } and the entries
// of a normal_map or of a list pattern are B deep unless they give their
// own size (issue 22, normmap.pov).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 angle 45 }
light_source { <-20, 20, -30> rgb 1 }
#default { pigment { rgb 0.9 } normal { bump_size 1.6 } finish { phong 0.5 } }
box { <-3.6, 0.2, 0>, <-0.2, 3.2, 1> normal { gradient x scallop_wave scale 0.5 } }
box { <0.2, 0.2, 0>, <3.6, 3.2, 1>
    normal { gradient y normal_map { [0.3 gradient x triangle_wave scale 0.4] [0.7 marble turbulence 0.4] } } }
box { <-3.6, -3.2, 0>, <-0.2, -0.2, 1>
    normal { checker normal { radial sine_wave frequency 8 rotate x * 90 } normal { gradient y 0.4 scale 0.3 } } }
box { <0.2, -3.2, 0>, <3.6, -0.2, 1> normal { bumps scale 0.3 } }

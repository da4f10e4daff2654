// Conformance: list patterns (checker, hexagon, brick, object) as plain
// normals — only the cells' edges tilt — and slope/aoi as normals: alone
// they leave the normal unchanged, with an altitude they tilt it, and they
// pick normal_map entries.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { rgb 0.7 } normal { hexagon 0.8 scale 0.4 } }
sphere { <-2.6, 1, 0>, 1 pigment { rgb <1, 0.8, 0.6> } normal { checker 0.8 scale 0.4 phase 0.3 sine_wave } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.6, 0.8, 1> } normal { slope { y, 0.2, 0.9 altitude <0, 1, 0.5>, 0, 2 } 1 slope_map { [0 <0, 1>] [1 <1, 0>] } scale 0.5 } }
sphere { <2.6, 1, 0>, 1 pigment { rgb <0.8, 1, 0.6> } normal { aoi normal_map { [0.5 bumps 0.8 scale 0.1] [0.7 ripples 1 scale 0.2] } } }
box { <-3.6, 0, 1.6>, <-1.6, 2.4, 2.4> pigment { rgb 0.8 } normal { brick 1 brick_size 0.5 mortar 0.08 } }
box { <-1, 0, 1.6>, <1, 2.4, 2.4> pigment { rgb 0.8 } normal { object { sphere { <0, 1.2, 1.6>, 0.8 } } 1 } }
box { <1.6, 0, 1.6>, <3.6, 2.4, 2.4> pigment { rgb 0.8 } normal { slope y 1 } }

// global_settings { number_of_waves N } sets how many sources ripples
// and waves sum, in pigments and normals alike, and applies to patterns
// read before it too (issue 22, normavg.pov: number_of_waves 1).
#version 3.7;
camera { orthographic location <0, 0, -10> look_at 0 right 8 * x up 6 * y }
light_source { <500, 500, -300> rgb 0.75 }
light_source { <-500, 50, -300> rgb 0.25 }
#default { finish { phong 1 phong_size 100 } }
#macro Tile(Texture, X, Y)
    plane { z, 0 texture { Texture } clipped_by { box { <X - 1.9, Y - 1.4, -1>, <X + 1.9, Y + 1.4, 1> } } }
#end
Tile(texture { pigment { rgb 1 } normal { waves 2.0 frequency 3 } }, -2, 1.5)
Tile(texture { pigment { rgb 1 } normal { ripples 2.0 translate <1, 1, 0> } }, 2, 1.5)
Tile(texture { pigment { waves color_map { [0 rgb 0] [1 rgb 1] } scale 0.5 } }, -2, -1.5)
Tile(texture { pigment { ripples color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } } }, 2, -1.5)
global_settings { assumed_gamma 1.0 number_of_waves 3 }

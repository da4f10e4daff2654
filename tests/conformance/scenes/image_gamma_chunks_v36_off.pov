// Before #version 3.7 a scene without assumed_gamma (gamma handling off)
// shows a PNG's values as stored whatever gamma chunks the file has
// (issue 22): gAMA 1/2.2, gAMA 1/1.8, gAMA with sRGB; an image's own
// `gamma` still decodes it (bottom row).
#version 3.6;
camera { orthographic location <0, 0, -10> look_at 0 right 8 * x up 6 * y }
#default { finish { ambient 1 diffuse 0 } }
#macro Ramp(Pigment, Y)
    plane { z, 0 pigment { Pigment scale <8, 1.5, 1> translate <-4, Y, 0> }
        clipped_by { box { <-4, Y, -1>, <4, Y + 1.5, 1> } } }
#end
Ramp(pigment { image_map { png "image_ramp_g22.png" } }, 1.5)
Ramp(pigment { image_map { png "image_ramp_g18.png" } }, 0)
Ramp(pigment { image_map { png "image_ramp_srgb.png" } }, -1.5)
Ramp(pigment { image_map { png "image_ramp_plain.png" gamma 2.2 } }, -3)

// Before #version 3.7, in a scene that sets assumed_gamma, a PNG's own
// gamma chunks decide how it is decoded (issue 22, desk.pov, whose later
// frames image_map povray's own earlier frames): an sRGB chunk, with or
// without gAMA, is the sRGB curve; a lone gAMA its gamma; a file with
// neither holds working-space values. Dark ramps show the difference.
#version 3.6;
global_settings { assumed_gamma 2.2 }
camera { orthographic location <0, 0, -10> look_at 0 right 8 * x up 6 * y }
#default { finish { ambient 1 diffuse 0 } }
#macro Ramp(File, Y)
    plane { z, 0 pigment { image_map { png File } scale <8, 1.2, 1> translate <-4, Y, 0> }
        clipped_by { box { <-4, Y, -1>, <4, Y + 1.2, 1> } } }
#end
Ramp("image_ramp_plain.png", 1.8)
Ramp("image_ramp_srgb.png", 0.6)
Ramp("image_ramp_srgbonly.png", -0.6)
Ramp("image_ramp_g22.png", -1.8)
Ramp("image_ramp_g18.png", -3)

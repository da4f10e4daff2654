// Before #version 3.7 an image whose gamma neither the scene (`gamma`)
// nor the file (a PNG's gAMA) gives holds working-space values, even with
// assumed_gamma 2.2 (issue 22, drums.pov): PNG without gAMA, GIF and PPM
// show their values as they are; `gamma 2.2` and a PNG with gAMA and sRGB
// chunks are decoded and re-encoded as in 3.7.
#version 3.6;
global_settings { assumed_gamma 2.2 }
camera { orthographic location <0, 0, -10> look_at 0 right 8 * x up 6 * y }
#default { finish { ambient 1 diffuse 0 } }
#macro Tile(Pig, X, Y)
    plane { z, 0 pigment { Pig scale 2.4 translate <X - 1.2, Y - 1.2, 0> }
        clipped_by { box { <X - 1.2, Y - 1.2, -1>, <X + 1.2, Y + 1.2, 1> } } }
#end
Tile(pigment { image_map { png "image_grid.png" } }, -2.7, 1.5)
Tile(pigment { image_map { gif "image_palette.gif" } }, 0, 1.5)
Tile(pigment { image_map { ppm "image_grid.ppm" } }, 2.7, 1.5)
Tile(pigment { image_map { png "image_grid.png" gamma 2.2 } }, -2.7, -1.5)
Tile(pigment { image_map { png "mesh_hf_bumps.png" } }, 0, -1.5)
Tile(pigment { image_map { jpeg "mesh_hf_bumps.jpg" } }, 2.7, -1.5)

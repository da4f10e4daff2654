// A transformation between a texture's pattern and its texture_map moves
// the map's textures too, as one after the map does: both planes show the
// same image in povray (entries scaled by 2 and turned by 30 degrees with
// the gradient).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 9, -7> look_at <0, 0, 0.5> angle 55 }
light_source { <-10, 20, -15> color rgb 1 }
#declare T1 = texture { pigment { checker rgb <1, 0.9, 0.6> rgb <0.2, 0.1, 0.05> scale 0.25 } }
#declare T2 = texture { pigment { radial frequency 8 color_map { [0 rgb <0.1, 0.3, 0.9>] [1 rgb 1] } } }
plane { y, 0
    texture { gradient x scale 2 rotate y * 30 texture_map { [0 T1] [0.5 T1] [0.5 T2] [1 T2] } }
    clipped_by { box { <-10, -1, 0.05>, <10, 1, 10> } } }
plane { y, 0
    texture { gradient x texture_map { [0 T1] [0.5 T1] [0.5 T2] [1 T2] } scale 2 rotate y * 30 }
    clipped_by { box { <-10, -1, -10>, <10, 1, -0.05> } } }

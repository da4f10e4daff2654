// Conformance: +Q0 and +Q1 show quick colours (povray 3.7, measured): each
// surface in its bottom texture layer's pigment colour, or quick_color, with
// no lighting, shadows, transparency or reflection; texture maps show their
// entries' colours; the background stays.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0,0,-10> look_at 0 right 6*x up 4*y }
background { rgb <0.2, 0.4, 0.6> }
box { <-3,1,0>, <-1,2,1> texture { checker texture { pigment { rgb <1,0,0> } } texture { pigment { rgb <0,1,0> } } } }
box { <-1,1,0>, <1,2,1> pigment { rgb <0.3,0.3,0.3> } finish { reflection 1 } }
box { <1,1,0>, <3,2,1> texture { pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } } texture { pigment { rgbf <0,0,1,0.5> } } }
sphere { <0,-1,0>, 0.8 pigment { rgb 0.5 quick_color rgb <1,1,0> } }
box { <-3,-2,0>, <-2,-1,1> pigment { image_map { png "image_grid.png" } } }

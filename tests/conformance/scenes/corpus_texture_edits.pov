// Editing a declared texture's items (issue 22, ballbox1/chess2): a
// pigment or normal block inside texture { T ... } or object { O ... }
// edits T's own pigment or normal, in the space T's transformations left
// it in; a pigment or normal identifier there replaces it untransformed,
// and a first normal after a transformation is not transformed either.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4.5, -8> look_at <0, 0.3, 0> angle 50 }
light_source { <-6, 10, -8> rgb 1 }
light_source { <8, 6, -4> rgb 0.4 }

#declare Striped = pigment { gradient x color_map { [0 rgb <0.9, 0.9, 0.2>] [1 rgb <0.2, 0.3, 0.8>] } }
#declare Ridges = normal { gradient z 0.8 scale 0.4 }
#declare Tiles = texture {
    pigment { checker rgb <0.85, 0.2, 0.15> rgb <0.95, 0.9, 0.8> }
    normal { bumps 0.6 scale 0.15 }
    finish { phong 0.4 }
    scale <0.5, 1, 0.25>
}
#declare Layers = texture { Tiles }
texture {
    pigment { gradient z color_map { [0 rgbt <0.1, 0.6, 0.2, 0.2>] [1 rgbt <1, 1, 1, 0.9>] } }
    scale 1.5 rotate y * 20
}
#declare Ball = sphere { 0, 0.8 texture { Tiles } }

plane { y, 0 texture { Tiles pigment { rotate y * 35 } normal { scale 2 } } }
box { <-3.6, 0, -1>, <-2.2, 1.4, 0.4> texture { Tiles pigment { Striped } } }
box { <-1.8, 0, -1>, <-0.4, 1.4, 0.4> texture { Tiles normal { Ridges } } }
object { Ball pigment { scale 0.6 rotate z * 30 } translate <0.6, 0.8, -1.6> }
box { <1.6, 0, -1>, <3.2, 1.4, 0.4> texture { Layers pigment { rotate x * 40 } finish { phong 0.9 } } }
sphere { <2.4, 0.5, -2.2>, 0.5
    texture { pigment { rgb <0.7, 0.75, 0.8> } scale <3, 1, 1> normal { gradient x 0.7 scale 0.2 } } }
sphere { <-2.6, 0.45, -2.2>, 0.45
    texture { Tiles pigment { quick_color rgb <1, 0, 0> } } }

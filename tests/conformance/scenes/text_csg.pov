// Conformance: text inside CSG. Letters cut out of a slab (difference),
// a text intersected with a sphere, a merge of text with a box, and an
// inverse text clipping: the inside of a glyph (holes by even-odd) decides.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0.5, 2.6, -5.5> look_at <0.5, 0.4, 0> angle 55 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 4, -9> color rgb 0.3 }
plane { y, -1.2 pigment { color rgb <0.5, 0.55, 0.6> } }

difference {
    box { <-2.2, 0.9, -0.1>, <1.4, 1.9, 0.2> }
    text { ttf "cyrvetic.ttf" "OBa8" 0.5, 0 scale 0.9 translate <-2.0, 1.1, -0.2> }
    pigment { rgb <0.9, 0.6, 0.3> }
}

intersection {
    text { ttf "timrom.ttf" "eRo" 1.5, 0 scale 1.2 translate <-2.2, -0.9, -0.8> }
    sphere { <-1.1, -0.5, -0.3>, 1.0 }
    pigment { rgb <0.4, 0.8, 1> }
}

merge {
    text { ttf "crystal.ttf" "Q@" 0.4, 0 translate <0.6, -0.8, -0.5> }
    box { <0.5, -1.0, -0.3>, <2.2, -0.7, 0.2> }
    pigment { rgb <0.7, 1, 0.5> }
}

text { ttf "timrom.ttf" "B" 0.3, 0 scale 1.5 translate <2.3, 0.7, -0.2>
    clipped_by { box { <2.5, 0.6, -0.5>, <4, 1.6, 0.5> } }
    pigment { rgb <1, 0.4, 0.6> } }

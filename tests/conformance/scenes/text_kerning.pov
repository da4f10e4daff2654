// Conformance: kerning pairs read from the fonts' kern tables ("AV",
// "To", "LT", ...), each line above the same letters set apart, and a
// string in the UTF-8 charset with accented (composite) glyphs.
#version 3.7;
global_settings { assumed_gamma 1.0 charset utf8 }

camera { location <2.6, 0.6, -6> look_at <2.6, 0.6, 0> angle 72 }
light_source { <-5, 8, -10> color rgb 1 }
background { rgb <0.2, 0.2, 0.22> }

text { ttf "timrom.ttf" "AVATAR To LTy" 0.1, 0 translate <-0.5, 2.3, 0> pigment { rgb <1, 0.85, 0.4> } }
text { ttf "timrom.ttf" "A V A T A R" 0.1, 0 translate <-0.5, 1.5, 0> pigment { rgb <0.7, 0.6, 0.4> } }
text { ttf "cyrvetic.ttf" "WAVE Yo PA" 0.1, 0 translate <-0.5, 0.6, 0> pigment { rgb <0.5, 1, 0.7> } }
text { ttf "timrom.ttf" "Éléphant ça où" 0.1, 0 translate <-0.5, -0.4, 0> pigment { rgb <0.6, 0.8, 1> } }
text { internal 2 "Zürich" 0.1, 0 translate <-0.5, -1.2, 0> pigment { rgb <1, 0.6, 0.6> } }
text { internal 1 "Tw" 0.1, 0 translate <3.6, -1.2, 0> pigment { rgb <1, 0.6, 1> } }

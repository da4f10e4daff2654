// Conformance: rotated, scaled and sheared text, and the offset argument
// (spacing added after each character, its y lifting each next one).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 1.2, -7> look_at <0, 0.3, 0> angle 60 }
light_source { <-5, 8, -10> color rgb 1 }
light_source { <8, -3, -6> color rgb 0.4 }
background { rgb <0.15, 0.18, 0.25> }

text { ttf "timrom.ttf" "Turn" 0.4, 0 rotate <0, 35, 0> scale 1.3 translate <-3.2, 1.2, 0> pigment { rgb <1, 0.8, 0.3> } }
text { ttf "cyrvetic.ttf" "Tilt" 0.25, 0 rotate <-50, 0, 15> scale <1.5, 0.8, 2> translate <0.6, 1.4, 0> pigment { rgb <0.4, 1, 0.6> } }
text { ttf "cyrvetic.ttf" "steps" 0.2, <0.1, 0.15, 0> scale 0.9 translate <-3.4, -1.4, 0> pigment { rgb <0.5, 0.7, 1> } }
text { ttf "timrom.ttf" "wide" 0.3, 0 matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 0> scale <1.6, 1, 1> translate <0.4, -1.5, -0.5> pigment { rgb <1, 0.5, 0.7> } }
text { ttf "crystal.ttf" "edge" 0.6, 0 rotate <0, 80, 0> translate <3.1, -0.4, 1> pigment { rgb <0.9, 0.9, 0.9> } }

// Conformance: text in each of the four fonts POV-Ray ships (serif,
// sans-serif, monospace, the logo font), seen from above and the side so
// caps and curved walls both show, casting shadows on a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <2.9, 3.4, -7.5> look_at <2.9, 0.9, 0> angle 56 }
light_source { <-8, 12, -10> color rgb 1 }
light_source { <10, 6, -6> color rgb 0.35 }
plane { y, -0.05 pigment { color rgb <0.55, 0.6, 0.65> } }

text { ttf "timrom.ttf" "Rag Quiz&@" 0.3, 0 pigment { rgb <0.95, 0.75, 0.2> } translate <0, 2.4, 0.5> }
text { ttf "cyrvetic.ttf" "Sample 0123" 0.3, 0 pigment { rgb <0.3, 0.85, 0.45> } translate <0, 1.5, 0> }
text { ttf "crystal.ttf" "mono {x};" 0.3, 0 pigment { rgb <0.4, 0.6, 1> } translate <0, 0.6, -0.5> }
text { ttf "povlogo.ttf" "P" 0.4, 0 pigment { rgb <1, 0.45, 0.35> } scale 1.4 translate <4.6, -0.05, -0.6> }
text { ttf "timrom.ttf" "gyp%" 0.3, 0 pigment { rgb <0.8, 0.5, 0.9> } rotate 90*x translate <0, 0.25, -1.2> }

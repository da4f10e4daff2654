// Accuracy study: anti-aliasing. A checker floor seen from above (its
// squares shrink to a few pixels at the top of the image), fine stripes on
// a sphere, thin wires and small text: edges and texture detail near and
// below a pixel, which only supersampling resolves.
// study-knobs: aa_threshold aa_depth jitter sampling_method quality
// study-baseline: +A0.3 +R3 -J +AM1
// study-reference: +A0.0 +R8 -J +AM1
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <-5, 10, -8> rgb 1 }
background { rgb <0.55, 0.65, 0.85> }
plane { y, 0 pigment { checker rgb 0.05, rgb 0.95 scale 0.5 } }
sphere {
    <-1.7, 1, 1>, 1
    pigment { gradient x color_map { [0.5 rgb <0.9, 0.2, 0.1>] [0.5 rgb 1] } scale 0.15 rotate z * 30 }
    finish { phong 0.6 }
}
#for (I, 0, 14)
    cylinder { <0.2 + I * 0.13, 0, 0>, <0.7 + I * 0.13, 2.6, 1.2>, 0.012 pigment { rgb <0.2, 0.4, 0.95> } }
#end
text {
    ttf "timrom.ttf" "frameray 0.9" 0.1, 0
    scale 0.45 translate <-1.6, 2.4, -1.5>
    pigment { rgb <0.95, 0.8, 0.2> }
}

// Accuracy study: fog. Distance fog and a ground fog layer over a row of
// columns on a reflective floor; the fog is only traced from Quality 9, and
// reflections of fogged objects need a few trace levels.
// study-knobs: max_trace aa_threshold quality
// study-baseline: +A0.3 +R3 -J Declare=MaxTrace=5
// study-reference: +A0.0 +R5 -J Declare=MaxTrace=20
#version 3.7;
#ifndef (MaxTrace) #declare MaxTrace = 5; #end
global_settings { assumed_gamma 1.0 max_trace_level MaxTrace }
camera { location <0, 1.5, -6> look_at <0, 1.2, 4> angle 60 }
light_source { <-6, 12, -8> rgb 1 }
background { rgb <0.5, 0.6, 0.8> }
fog { distance 30 color rgb <0.7, 0.75, 0.8> }
fog { fog_type 2 distance 12 fog_offset 0.1 fog_alt 0.4 color rgbt <0.9, 0.9, 1, 0.3> }
plane { y, 0 pigment { checker rgb 0.2, rgb 0.6 } finish { reflection 0.35 } }
#for (I, 0, 9)
    cylinder { <-2.2, 0, I * 2.5>, <-2.2, 3, I * 2.5>, 0.35 pigment { rgb <0.9, 0.85, 0.7> } }
    cylinder { <2.2, 0, I * 2.5>, <2.2, 3, I * 2.5>, 0.35 pigment { rgb <0.9, 0.85, 0.7> } }
#end
sphere { <0, 0.8, 3>, 0.8 pigment { rgb <0.8, 0.2, 0.2> } finish { reflection 0.5 phong 0.8 } }

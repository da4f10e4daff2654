// Accuracy study: deep recursion. Two facing mirrors make a corridor of
// reflections that fade by 0.8 per bounce; polished spheres and a glass
// sphere (reflection + refraction: two children per hit) sit between them.
// max_trace_level cuts the corridor short, adc_bailout prunes faint rays.
// study-knobs: max_trace adc_bailout aa_threshold quality
// study-baseline: +A0.3 +R3 -J Declare=MaxTrace=5 Declare=AdcBailout=0.0039
// study-reference: +A0.0 +R4 -J Declare=MaxTrace=40 Declare=AdcBailout=0.00001
#version 3.7;
#ifndef (MaxTrace) #declare MaxTrace = 5; #end
#ifndef (AdcBailout) #declare AdcBailout = 1 / 255; #end
global_settings { assumed_gamma 1.0 max_trace_level MaxTrace adc_bailout AdcBailout }
camera { location <0.6, 1.6, -2.6> look_at <-0.4, 1.0, 3> angle 60 }
light_source { <1, 4, -1> rgb 1 }
light_source { <-1.5, 3, 4> rgb 0.4 }
background { rgb <0.1, 0.1, 0.15> }
plane { y, 0 pigment { checker rgb <0.8, 0.7, 0.5>, rgb <0.3, 0.2, 0.1> } finish { reflection 0.2 } }
plane { y, 4 pigment { rgb 0.9 } }
#declare Mirror = finish { ambient 0 diffuse 0.05 reflection 0.8 }
box { <-2, 0, 5>, <2, 4, 5.1> pigment { rgb <0.9, 1, 0.95> } finish { Mirror } }
box { <-2, 0, -3.1>, <2, 4, -3> pigment { rgb <0.9, 1, 0.95> } finish { Mirror } }
sphere { <-0.9, 0.6, 2>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } finish { reflection 0.6 phong 0.8 } }
sphere { <0.9, 0.5, 3>, 0.5 pigment { rgb <0.2, 0.5, 0.9> } finish { reflection 0.7 phong 0.8 } }
sphere {
    <0.1, 1.0, 1>, 0.45
    pigment { rgbf <0.95, 1, 0.95, 0.9> }
    finish { reflection 0.1 phong 0.9 }
    interior { ior 1.5 }
}

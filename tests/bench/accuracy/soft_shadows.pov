// Accuracy study: soft shadows. One large area light over a few objects:
// the grid size (AreaSize x AreaSize lights) sets how smooth the penumbra
// is, the adaptive level how many grid points are actually shadow-tested.
// study-knobs: area_size area_adaptive aa_threshold quality
// study-baseline: +A0.3 +R3 -J Declare=AreaSize=5 Declare=AreaAdaptive=1
// study-reference: +A0.05 +R3 -J Declare=AreaSize=17 Declare=AreaAdaptive=4
#version 3.7;
#ifndef (AreaSize) #declare AreaSize = 5; #end
#ifndef (AreaAdaptive) #declare AreaAdaptive = 1; #end
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -8> look_at <0, 0.6, 0> angle 50 }
light_source {
    <-3, 7, -3> rgb 1
    area_light <4, 0, 0>, <0, 0, 4>, AreaSize, AreaSize
    adaptive AreaAdaptive
}
light_source { <5, 8, -6> rgb 0.15 shadowless }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <-1.5, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.3> } finish { phong 0.5 } }
box { <0.3, 0, -0.8>, <2, 1.5, 0.8> rotate y * 25 pigment { rgb <0.3, 0.6, 0.9> } }
cylinder { <0, 0, 2>, <0, 2.5, 2>, 0.3 pigment { rgb <0.4, 0.9, 0.4> } }
#for (I, 0, 5)
    cylinder { <-2.5 + I * 0.9, 0.4, -2.5>, <-2.5 + I * 0.9, 0.4, -1>, 0.08 pigment { rgb 0.6 } }
#end

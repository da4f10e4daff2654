// Accuracy study: participating media (issue 25). Atmospheric scattering
// media lit by a spotlight through a slatted screen (light shafts), and a
// sphere of emitting, absorbing media with a turbulent density.
// study-knobs: media_intervals media_samples media_aa_level media_aa_threshold
// study-baseline: -A Declare=MediaIntervals=1 Declare=MediaSamples=5 Declare=MediaAaLevel=3 Declare=MediaAaThreshold=0.1
// study-reference: -A Declare=MediaIntervals=10 Declare=MediaSamples=40 Declare=MediaAaLevel=5 Declare=MediaAaThreshold=0.01
#version 3.7;
#ifndef (MediaIntervals) #declare MediaIntervals = 1; #end
#ifndef (MediaSamples) #declare MediaSamples = 5; #end
#ifndef (MediaAaLevel) #declare MediaAaLevel = 3; #end
#ifndef (MediaAaThreshold) #declare MediaAaThreshold = 0.1; #end
#declare Sampling = media { intervals MediaIntervals samples MediaSamples
    aa_level MediaAaLevel aa_threshold MediaAaThreshold }
global_settings { assumed_gamma 1 }
camera { location <0, 3, -12> look_at <0, 2, 0> angle 60 }
media { Sampling scattering { 1, rgb 0.02 } }
light_source { <0, 14, 6> color rgb 2.5 spotlight point_at <0, 0, 0> radius 18 falloff 24
    tightness 1 media_attenuation on }
light_source { <-8, 6, -12> color rgb 0.3 shadowless media_interaction off }
// The slatted screen the spotlight shines through.
union {
  #declare I = -4;
  #while (I <= 4)
    box { <I - 0.3, 9, -4>, <I + 0.3, 9.2, 8> }
    #declare I = I + 1;
  #end
  pigment { rgb 0.2 }
}
plane { y, 0 pigment { checker rgb 0.7, rgb 0.4 } }
sphere { <3, 2, 0>, 1.8 hollow pigment { rgbt 1 }
  interior { media { Sampling emission <1, 0.5, 0.2> absorption 0.5
    density { spherical turbulence 0.6 color_map { [0 rgb 0] [0.6 rgb 1] [1 rgb 2] } scale 1.8 } } }
  translate 0 }
box { <-4, 0, -1>, <-2, 2, 1> pigment { rgb <0.3, 0.5, 0.9> } }

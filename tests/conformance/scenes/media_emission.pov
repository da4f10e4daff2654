// Emitting and absorbing media in hollow containers: constant media, a
// density pattern with a colour map, samples, intervals and aa settings,
// a non-hollow container (povray 3.7 shows no media in it).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -7> look_at <0, 0.6, 0> angle 50 }
background { rgb <0.2, 0.25, 0.3> }
light_source { <4, 8, -6> rgb 1 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.3 } }
// constant emission and absorption: one interval whatever intervals says
box { <-1, -1, -1>, <1, 1, 1> scale 0.7 translate <-2.2, 0, 0>
  pigment { rgbt 1 } hollow
  interior { media { emission <0.6, 0.3, 0.1> absorption <0.2, 0.5, 0.8> intervals 4 } } }
// spherical density with a colour map, few samples, default aa
sphere { 0, 1 translate <0, 0.2, 0>
  pigment { rgbt 1 } hollow
  interior { media { emission 1.2 samples 4
    density { spherical color_map { [0 rgb 0] [0.5 rgb <1, 0.5, 0.2>] [1 rgb <1, 1, 0.6>] } } } } }
// gradient density, two intervals, aa_level 1 (no subdivision)
box { <-1, -1, -1>, <1, 1, 1> scale <0.6, 0.9, 0.6> translate <2.2, 0, 0>
  pigment { rgbt 1 } hollow
  interior { media { emission <0.2, 0.9, 0.4> absorption 0.5 intervals 2 samples 3 aa_level 1
    density { gradient y scale 2 translate -y } } } }
// not hollow: no media in povray 3.7
sphere { 0, 0.5 translate <0, 1.6, 1.5> pigment { rgbt 1 } interior { media { emission 1 } } }

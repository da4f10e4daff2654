// Media: emitting and absorbing interior media with density patterns,
// scattering interior media lit by a point light (shadow rays through
// media), and scattering air lit by a spotlight (its volume cuts intervals).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -9> look_at <0, 1, 0> angle 55 }
background { rgb <0.1, 0.1, 0.15> }
media { scattering { 1, 0.03 } samples 6 }
light_source { <0, 7, 1> rgb 3 spotlight point_at <0, 0, 1> radius 12 falloff 20 }
light_source { <-6, 8, -4> rgb 0.7 media_interaction off }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.3 } }
sphere { <-2.3, 1.2, 0>, 1.1 pigment { rgbt 1 } hollow
  interior { media { emission 0.8 absorption 0.4 samples 8
    density { spherical turbulence 0.3 color_map { [0 rgb 0] [0.6 rgb <1, 0.5, 0.2>] [1 rgb <1, 1, 0.6>] } } } }
  translate <0, 0, 0> }
box { <-1, 0, -1>, <1, 2.2, 1> pigment { rgbt 1 } hollow translate <2.3, 0.01, 0>
  interior { media { scattering { 2, 0.15 } absorption 0.1 samples 4
    density { bozo scale 0.5 color_map { [0.3 rgb 0] [0.7 rgb 1] } } } } }
sphere { <0, 0.8, 2.5>, 0.8 pigment { rgb <0.2, 0.5, 0.9> } }

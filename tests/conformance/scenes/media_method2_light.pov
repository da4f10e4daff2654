// Media sampling method 2 with light: a spotlight's shaft scattered in a
// box of media (the ray cut where it enters and leaves the cone, the
// intervals shared by `ratio`), and shadow rays through an absorbing
// sphere whose density falls off from its centre (each shadow ray takes
// `samples` samples per interval, as povray 3.7 does).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -10> look_at <0, 0.5, 0> angle 55 }
background { rgb <0.05, 0.05, 0.1> }
light_source { <0, 6, 0> color rgb 1.5 spotlight point_at <0.5, 0, 0> radius 10 falloff 16 }
light_source { <-8, 3, -6> color rgb 0.4 media_interaction off }
plane { y, -1.5 pigment { checker rgb 0.8 rgb 0.3 } }
box { <-4, -1.4, -2>, <4, 4, 2> hollow pigment { rgbf 1 }
  interior { media { method 2 intervals 5 samples 3
    scattering { 1, 0.08 } absorption 0.02 } } }
sphere { <-2.2, -0.3, -3.5>, 1 hollow pigment { rgbf 1 }
  interior { media { method 2 intervals 2 samples 4 absorption <0.8, 1.6, 2.4>
    density { spherical color_map { [0 rgb 0] [1 rgb 1.5] } } } } }

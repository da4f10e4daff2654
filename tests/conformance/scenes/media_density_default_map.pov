// A density pattern given without a colour map takes the same default map
// as in a pigment (measured with povray 3.7: bozo, marble, wood, agate and
// radial densities cast their coloured default maps' shadows; spotted and
// gradient the black-to-white ramp).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 9, -0.01> look_at <0, 0, 0> angle 70 }
light_source { <0, 40, 0> rgb 1 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
box { <-1.4, 1, -1.4>, <1.4, 2, 1.4> pigment { rgbt 1 } hollow
  interior { media { absorption 1 method 3 samples 2 intervals 1 density { bozo scale 0.7 } } }
  translate <-3.2, 0, 1.6> }
box { <-1.4, 1, -1.4>, <1.4, 2, 1.4> pigment { rgbt 1 } hollow
  interior { media { absorption 1 method 3 samples 2 intervals 1 density { marble scale 2 } } }
  translate <0, 0, 1.6> }
box { <-1.4, 1, -1.4>, <1.4, 2, 1.4> pigment { rgbt 1 } hollow
  interior { media { absorption 1 method 3 samples 2 intervals 1 density { wood scale 0.5 } } }
  translate <3.2, 0, 1.6> }
box { <-1.4, 1, -1.4>, <1.4, 2, 1.4> pigment { rgbt 1 } hollow
  interior { media { absorption 1 method 3 samples 2 intervals 1 density { agate scale 2 } } }
  translate <-3.2, 0, -1.6> }
box { <-1.4, 1, -1.4>, <1.4, 2, 1.4> pigment { rgbt 1 } hollow
  interior { media { absorption 1 method 3 samples 2 intervals 1 density { radial } } }
  translate <0, 0, -1.6> }
box { <-1.4, 1, -1.4>, <1.4, 2, 1.4> pigment { rgbt 1 } hollow
  interior { media { absorption 1 method 3 samples 2 intervals 1 density { spotted scale 0.7 } } }
  translate <3.2, 0, -1.6> }

// The light reaching media samples through the media of a difference:
// a shadow ray enters the shell through the subtracted operand's surface
// (whose own normal points the wrong way), and the media of the shell
// dims it only between its walls, as povray 3.7 does.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.85, 1, -6> look_at <0.85, 1, 0> angle 40 }
background { rgb 0 }
light_source { <0.85, 10, 0> color rgb 1 }
box { <-1, 0.3, -1>, <2.5, 1.3, 1> hollow pigment { rgbf 1 }
  interior { media { scattering { 1, 0.5 } } } }
difference {
  box { <-3, 3, -3>, <0, 4, 3> }
  box { <-4, 3.25, -4>, <1, 3.75, 4> }
  hollow pigment { rgbf 1 }
  interior { media { absorption 1 } } }
difference {
  sphere { <2.2, 3.5, 0>, 0.8 }
  sphere { <2.2, 3.5, 0>, 0.5 }
  hollow pigment { rgbf 1 }
  interior { media { absorption 1.5 } } }

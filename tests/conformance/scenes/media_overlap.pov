// Media of overlapping containers sampled together, as povray 3.7 does:
// the summed scattering is scattered with the mean of the media's phase
// functions (a media that does not scatter counts as isotropic), and the
// container the ray entered first gives the sampling settings.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -10> look_at <0, 0.5, 0> angle 40 }
background { rgb 0 }
light_source { <0, 30, 60> color rgb 1 }
// Left: Mie hazy and murky slabs, their upper halves inside an absorbing box.
box { <-4, 1.2, -2>, <0, 2.2, 2> hollow pigment { rgbf 1 }
  interior { media { scattering { 2, 0.03 } } } }
box { <-4, 0, -2>, <0, 1, 2> hollow pigment { rgbf 1 }
  interior { media { scattering { 3, 0.03 } } } }
box { <-2.5, 0.5, -3>, <0, 3, 3> hollow pigment { rgbf 1 }
  interior { media { absorption 0.05 } } }
// Right: Rayleigh and Henyey-Greenstein slabs overlapping each other.
box { <0.2, 1.2, -2>, <4, 2.2, 2> hollow pigment { rgbf 1 }
  interior { media { scattering { 4, 0.05 } } } }
box { <2, 0, -2.5>, <3.7, 1.7, 2.5> hollow pigment { rgbf 1 }
  interior { media { scattering { 5, 0.03 eccentricity 0.6 } } } }
// Bottom: two emitting boxes with samples 4 and 2; the wider one is
// entered first.
box { <-4, -2.2, -2>, <4, -0.8, 2> hollow pigment { rgbf 1 }
  interior { media { samples 4 emission 0.1
    density { gradient z scale 1.3 color_map { [0 rgb 0] [0.3 rgb 1] [0.6 rgb 0.2] [1 rgb 0.5] } } } } }
box { <-1, -1.5, -1.5>, <3.6, -0.4, 1.5> hollow pigment { rgbf 1 }
  interior { media { samples 2 emission 0.05
    density { gradient z scale 0.7 color_map { [0 rgb 0] [0.3 rgb 1] [0.6 rgb 0.2] [1 rgb 0.5] } } } } }

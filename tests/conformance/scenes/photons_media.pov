// Photons in media: a glass sphere focuses a point light's photons into a
// box of scattering media (pass_through, so photons enter it on their way
// to the sphere); the photons left along their refracted paths show the
// focused beam, gathered in the media's sampling. The sphere stops the
// light's own shadow rays (it refracts the light's photons), so behind
// it the media and the floor are lit by photons only. jitter 0: the
// photons leave the light in povray's exact rings and media photons sit
// at the middle of their steps.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  photons { spacing 0.01 jitter 0 media 60 }
}
camera { location <0, 5, -7> look_at <0.5, 0.8, 0> angle 45 }
light_source { <-10, 1.2, 0>, rgb 1 photons { refraction on reflection off } }
plane { y, 0 pigment { rgb 0.6 } finish { ambient 0.05 diffuse 0.8 } }
box { <-3, 0.01, -1.5>, <4, 2.4, 1.5> hollow
  pigment { rgbf 1 }
  interior { media { scattering { 1, rgb 0.25 } method 3 intervals 1 samples 3 } }
  photons { pass_through }
}
sphere { <-1.5, 1.2, 0>, 0.7
  pigment { rgbf <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 specular 0.5 roughness 0.01 }
  interior { ior 1.5 }
  photons { target refraction on reflection off collect off }
}

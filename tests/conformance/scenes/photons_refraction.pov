// Photon mapping: the caustic of a glass sphere and the shadow it casts
// with photons on (the refracting target stops the light's shadow rays;
// the photons bring it back, focused). jitter 0: the photons leave the
// light in povray's exact rings.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  photons { spacing 0.01 jitter 0 }
}
camera { location <0, 5, -6> look_at <0, 0.5, 0> angle 40 }
light_source { <3, 8, 2>, rgb 1 photons { refraction on reflection off } }
plane { y, 0 pigment { rgb 0.6 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <0, 1, 0>, 1
  pigment { rgbf <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 specular 0.5 roughness 0.01 }
  interior { ior 1.5 }
  photons { target refraction on reflection off collect off }
}
box { <1.4, 0, -1.6>, <2, 0.6, -1> pigment { rgb <0.8, 0.3, 0.2> } }

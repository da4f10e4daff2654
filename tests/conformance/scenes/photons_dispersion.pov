// Photon mapping with dispersion: a glass prism under a parallel light
// spreads the photons it refracts into a spectrum on the floor (each white
// photon splits into the interior's bands).
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 10
  photons { spacing 0.01 jitter 0 }
}
camera { location <4, 7, -7> look_at <4.5, 0, 0> angle 60 }
light_source { <-2.5, 5, 0>, rgb 0.9 parallel point_at <0, 1.5, 0>
  photons { refraction on reflection on } }
plane { y, 0 pigment { rgb 0.5 } finish { ambient 0.03 diffuse 0.8 } }
// A triangular bar along z, its apex up.
intersection {
  plane { -y, 0 }
  plane { <-0.866, 0.5, 0>, 0.866 }
  plane { <0.866, 0.5, 0>, 0.866 }
  box { <-2, -1, -1.5>, <2, 2, 1.5> }
  scale 0.7 rotate <0, 0, 10> translate <0, 1.2, 0>
  pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 dispersion 1.06 dispersion_samples 12 }
  photons { target refraction on reflection on collect off }
}

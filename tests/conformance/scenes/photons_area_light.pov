// Photon mapping from an area light: with `photons { area_light }` each
// point of the 3x3 grid shoots its own beam (spacing times sqrt(9), a ninth
// of the colour), so the glass sphere focuses nine caustics instead of one.
// jitter 0: povray's exact rings (8658 photons shot, as frameray).
#version 3.7;
global_settings {
  assumed_gamma 1.0
  photons { spacing 0.02 autostop 0 jitter 0 }
}
camera { location <0, 6, -6> look_at <0, 0.5, 0> angle 40 }
light_source { <0, 10, 0>, rgb 1
  area_light 4*x, 4*z, 3, 3
  photons { refraction on reflection on area_light } }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.7 } }
sphere { <0, 1.5, 0>, 1
  pigment { rgbf <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 }
  photons { target refraction on } }

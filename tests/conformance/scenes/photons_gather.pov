// Photon mapping: the gather radius povray estimates from the photons.
// A glass ball focuses a light almost in its focal plane onto a wall:
// the photons crowd so densely there that povray's estimated radius
// (from their mean density) is a fraction of the spacing, and the rings
// in which the photons were shot stay sharp on the wall, with dark gaps
// between the outer rings where a gather finds no photon within the
// radius but many within three times it.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 10
  photons { spacing 0.01 jitter 0 autostop 0 }
}
camera { location <-1.5, 1.3, -5> look_at <0, 1, 0.5> angle 30 }
light_source { <-20, 1, 0.5>, rgb 1 photons { refraction on reflection on } }
plane { x, 0 pigment { rgb 0.8 } finish { ambient 0.05 diffuse 0.7 } }
sphere { <-1.4, 1, 0.5>, 0.9
  pigment { rgbf <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 reflection 0.05 specular 0.6 roughness 0.005 }
  interior { ior 1.5 }
  photons { target refraction on reflection on collect off } }

// Photon shooting must not depend on the thread count: jittered photons
// (the default jitter 0.4), a spotlight area light shooting from each of
// its grid points, refraction with dispersion and a mirror, and `count`
// picking the spacing. Rendered at +WT1 and +WT2; the images must be
// byte-identical (povray's own differ between thread counts).
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 8
  photons { count 20000 autostop 0 }
}
camera { location <0, 5, -6> look_at <0, 0.5, 0> angle 45 }
light_source { <2, 8, 1>, rgb 1
  spotlight point_at <0, 1, 0> radius 20 falloff 30
  area_light 1.5*x, 1.5*z, 2, 2
  photons { refraction on reflection on area_light } }
plane { y, 0 pigment { rgb 0.7 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-0.6, 1, 0>, 0.8
  pigment { rgbf <1, 0.95, 0.9, 0.95> }
  finish { ambient 0 diffuse 0 reflection 0.1 }
  interior { ior 1.5 dispersion 1.05 dispersion_samples 5 }
  photons { target refraction on reflection on collect off } }
box { <-0.5, -0.5, -0.05>, <0.5, 0.5, 0.05> rotate <0, 30, 20> translate <1.2, 1, 0.5>
  pigment { rgb 1 } finish { ambient 0 diffuse 0 reflection 1 }
  photons { target 0.7 reflection on collect off } }

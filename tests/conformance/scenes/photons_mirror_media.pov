// Photons in media and on a floor, reflected by a mirror standing in the
// media (a cut-down of the corpus scene advanced/optics.pov): a narrow
// spotlight beam crosses a box of scattering media, a mirror at 45
// degrees turns it, and the turned beam leaves the box. The photons of
// the turned beam travel level with the floor: povray keeps a photon's
// direction to pi/127 only, so they arrive exactly parallel to it and do
// not light it; near the box's walls its flattened gather leaves the
// floor's own neighbourhood to the floor's photons.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5
  photons { count 150000 max_trace_level 9 media 100, 2 jitter 0 } }
#default { finish { ambient 0 } }
camera { location <0, 18, 0> right x*4/3 look_at <0, 0, 0> angle 35 }
light_source { <0, 18, 0>, rgb 0.25 photons { refraction off reflection off }
  media_interaction off }
light_source { <-150, 0.5, 0>, rgb <1.2, 1, 1.5>
  spotlight radius 0.3 falloff 0.35 point_at <0, 0.5, 0>
  photons { refraction on reflection on } }
box { <-100, -1, -100>, <100, 0, 100>
  texture { pigment { checker rgb 0.9, rgb <0.2, 0, 0.4> } finish { brilliance 0.25 } } }
box { <-7, -0.1, -3>, <6, 1, 4> hollow
  texture { pigment { rgbf 1 } }
  interior { media { scattering { 1, rgb 1 extinction 0 } method 3 intervals 1 samples 4 } }
  photons { target } }
box { <-0.1, -0.1, -1>, <0, 1, 1>
  texture { pigment { rgb 1 } finish { ambient 0 diffuse 0 reflection 1 } }
  rotate -45*y translate <-1, 0, 0> }

// Scene-level media: scattering and absorbing air lit by a spotlight with
// shafts behind an opaque slab, a light with media_attenuation.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -9> look_at <0, 1, 0> angle 55 }
background { rgb <0.1, 0.1, 0.15> }
media { scattering { 1, 0.04 } absorption 0.01 intervals 1 samples 6 }
light_source { <0, 6, 2> rgb 4 spotlight point_at <0, 0, 2> radius 15 falloff 25 }
light_source { <6, 3, -6> rgb 0.5 media_interaction off media_attenuation on }
plane { y, 0 pigment { rgb 0.6 } }
box { <-1.5, 3, 1>, <1.5, 3.2, 3> pigment { rgb <0.8, 0.2, 0.2> } }
sphere { <-2.5, 1, 1>, 1 pigment { rgb <0.2, 0.5, 0.9> } }

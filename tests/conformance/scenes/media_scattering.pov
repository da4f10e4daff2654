// Scattering media lit by lights: the five phase functions, extinction,
// a light that does not interact with media, shadows through media.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at <0, 0.3, 0> angle 55 }
background { rgb 0.05 }
light_source { <-3, 6, 5> rgb 0.8 }
light_source { <0, 3, -9> rgb 0.4 media_interaction off }
plane { y, -1 pigment { rgb 0.4 } }
#declare Slab = box { <-0.5, -0.9, -0.5>, <0.5, 1, 0.5> pigment { rgbt 1 } hollow }
object { Slab translate x*-3.2 interior { media { scattering { 1, 0.3 } } } }
object { Slab translate x*-1.6 interior { media { scattering { 2, 0.06 } } } }
object { Slab interior { media { scattering { 3, <0.03, 0.02, 0.012> extinction 0.5 } } } }
object { Slab translate x*1.6 interior { media { scattering { 4, <0.1, 0.2, 0.4> } } } }
object { Slab translate x*3.2 interior { media { scattering { 5, 0.4 eccentricity -0.4 } absorption 0.3 } } }

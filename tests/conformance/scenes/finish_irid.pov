// irid { amount thickness turbulence }: the thin-film tint of diffuse light
// and highlights, 1 + amount * cos(2 pi thickness (cos view + cos light) /
// wavelength) per channel, the film thickness turbulated in world space;
// irid_wavelength in global_settings and its default.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 0.9, 0> angle 48 }
light_source { <-10, 20, -15> rgb 1 }
light_source { <12, 8, -10> rgb 0.4 }
plane { y, 0 pigment { rgb 0.6 } finish { irid { 0.4 thickness 0.3 turbulence 0.6 } } }
sphere { <-3, 1, 0>, 1 pigment { rgb <0.9, 0.5, 0.3> } finish { diffuse 0.6 irid { 0.35 thickness 0.1 } } }
sphere { <-1, 1, 0>, 1 pigment { rgb 0.8 } finish { diffuse 0.5 phong 0.6 irid { 0.5 thickness 0.4 turbulence 0.3 } } }
sphere { <1, 1, 0>, 1 pigment { rgb <0.3, 0.6, 0.9> } finish { specular 0.5 roughness 0.02 irid { 0.25 thickness 1.2 turbulence 1 } } scale <1, 1, 0.5> translate z }
sphere { <3, 1, 0>, 1 pigment { rgb <0.8, 0.9, 0.5> } finish { irid { 0.6 thickness 0.05 } } }

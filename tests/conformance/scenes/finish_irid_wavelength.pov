// irid under a changed irid_wavelength.
#version 3.7;
global_settings { assumed_gamma 1.0 irid_wavelength rgb <0.3, 0.55, 0.9> }
camera { location <0, 3, -9> look_at <0, 0.9, 0> angle 48 }
light_source { <-10, 20, -15> rgb 1 }
plane { y, 0 pigment { rgb 0.6 } finish { irid { 0.5 thickness 0.2 turbulence 0.8 } } }
sphere { <-1.5, 1, 0>, 1 pigment { rgb 0.8 } finish { phong 0.5 irid { 0.7 thickness 0.25 } } }
sphere { <1.5, 1, 0>, 1 pigment { rgb <0.6, 0.8, 1> } finish { irid { 0.4 thickness 0.6 turbulence 0.5 } } }

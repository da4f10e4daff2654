// Iridescence tints what a surface mirrors, not only its diffuse light
// (fact from povray 3.7's trace.cpp ComputeReflection): a reflective
// iridescent sphere and a transparent one over a checker (advanced/diffract).
#version 3.7;
global_settings { assumed_gamma 1.0 irid_wavelength <0.25, 0.18, 0.14> }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.8, 0.6>] [1 rgb <0.3, 0.4, 0.9>] } } }
plane { y, 0 pigment { checker rgb 0.9 rgb <0.2, 0.3, 0.4> scale 0.5 } }
sphere { <-1.2, 1, 0>, 1
    pigment { rgb 0.1 }
    finish { diffuse 0.2 reflection 0.8 irid { 0.5 thickness 0.4 turbulence 0 } } }
sphere { <1.2, 1, 0>, 1
    pigment { rgbf <1, 1, 1, 0.9> }
    finish { diffuse 0.1 specular 0.5 reflection 0.3 irid { 0.35 thickness 0.25 turbulence 0.3 } }
    interior { ior 1.45 } }

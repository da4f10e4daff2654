// Fresnel reflection on glass and water-like surfaces, with and without
// conserve_energy; transparent objects cast no shadow here so only the
// surface optics are tested.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2.2, -6> look_at <0, 0.7, 0> angle 45 }
light_source { <-10, 20, -15> rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.2, 0.3, 0.6> scale 0.5 } }
plane { z, 6 pigment { checker rgb <0.8, 0.3, 0.2> rgb <0.9, 0.9, 0.6> } finish { ambient 0.4 } }
sphere { <-1.6, 1, 0>, 1 pigment { rgbf <0.9, 1, 0.95, 0.95> } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel } } interior { ior 1.5 } no_shadow }
sphere { <0.6, 0.8, -0.5>, 0.8 pigment { rgbt <1, 0.9, 0.8, 0.8> } finish { ambient 0 diffuse 0.1 reflection { 0.05, 0.8 fresnel } conserve_energy } interior { ior 1.33 } no_shadow }
box { <1.6, 0.01, -0.3>, <2.6, 1.6, 0.7> rotate y*-20 pigment { rgbft <0.6, 0.9, 0.7, 0.4, 0.4> } finish { ambient 0.05 diffuse 0.2 reflection { 0.3 fresnel } } interior { ior 2.0 } no_shadow }

// The camera inside a refracting object: rays start with its ior, so a
// fresnel surface seen from inside shows total internal reflection.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 1, -3> look_at <0, 1.5, 0> angle 60 }
light_source { <-3, 10, -8> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb <0.6, 0.2, 0.2> } }
plane { -y, -2 pigment { rgbt <0.8, 0.9, 1, 0.7> } finish { ambient 0.05 diffuse 0.1 reflection { 0, 1 fresnel } } interior { ior 1.33 } no_shadow }
sphere { <0, 1, 1>, 0.7 pigment { rgb <0.2, 0.5, 0.9> } }
sphere { <0, 5, 8>, 2 pigment { rgb <1, 0.9, 0.3> } finish { ambient 1 } }

// Total internal reflection in prisms, against emissive walls so every
// path is visible; max_trace_level deep enough for the bounces.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 ambient_light 0 }
camera { location <0, 0.5, -6> look_at <0, 0, 0> angle 50 }
background { rgb <0.2, 0.4, 0.6> }
plane { y, -3 pigment { checker rgb <1, 0.5, 0> rgb <0.5, 0.2, 0> } finish { emission 1 diffuse 0 } }
plane { -y, -3 pigment { checker rgb <0, 1, 0.5> rgb <0, 0.4, 0.3> } finish { emission 1 diffuse 0 } }
plane { -z, -8 pigment { checker rgb <0.6, 0.6, 0.9> rgb <0.2, 0.2, 0.4> } finish { emission 1 diffuse 0 } }
intersection { box { -1, 1 } plane { <0, -1, 1>, 0 } translate x*-1.3 pigment { rgbt <1, 0.8, 0.6, 0.5> } finish { ambient 0 diffuse 0 reflection { 0, 0.5 fresnel } } interior { ior 1.5 } }
intersection { box { -1, 1 } plane { <1, 0, 1>, 0 } rotate y*20 translate x*1.3 pigment { rgbf <0.8, 1, 1, 0.9> } finish { ambient 0 diffuse 0 reflection 0.2 } interior { ior 1.7 } }

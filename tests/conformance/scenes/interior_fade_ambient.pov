// Interior fade as povray 3.7 applies it: at a surface reached through a
// fading interior the light arriving there, its reflection and what it
// lets through are faded; its ambient and emission are not (measured: a
// glass slab's back face keeps its whole ambient).
#version 3.7;
global_settings { assumed_gamma 1 ambient_light 1 max_trace_level 5 }
camera { location <0, 1.5, -7> look_at <0, 0, 0> angle 50 }
background { rgb <0.3, 0.4, 0.5> }
light_source { <-6, 10, -8> rgb 1 }
plane { z, 3 pigment { checker rgb 1 rgb 0.2 } finish { ambient 0.3 } }
#declare Glass = interior { ior 1 fade_distance 0.5 fade_power 1 }
// Slabs: ambient only, diffuse only, both, and emission with reflection.
box { <-3.2, -0.8, -0.5>, <-1.8, 0.8, 0.5> pigment { rgbf <1, 0.9, 0.8, 0.9> } finish { ambient 0.5 diffuse 0 } interior { Glass } }
box { <-1.5, -0.8, -0.5>, <-0.1, 0.8, 0.5> pigment { rgbf <0.8, 0.9, 1, 0.9> } finish { ambient 0 diffuse 0.6 } interior { Glass } }
box { <0.2, -0.8, -0.5>, <1.6, 0.8, 0.5> pigment { rgbt <1, 1, 1, 0.8> } finish { ambient 0.4 diffuse 0.4 phong 0.5 } interior { Glass fade_power 1001 } }
sphere { <2.6, 0, 0>, 0.8 pigment { rgbf <0.9, 1, 0.9, 0.85> } finish { emission 0.3 diffuse 0.2 reflection 0.2 } interior { ior 1.3 fade_distance 1 fade_power 2 } }

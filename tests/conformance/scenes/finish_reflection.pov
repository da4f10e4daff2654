// Reflection as a float, a colour, and the 3.7 reflection block: falloff,
// exponent and metallic; metallic highlights.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
camera { location <0, 3.5, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-10, 20, -15> rgb 1 }
light_source { <12, 8, -10> rgb 0.4 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.85> rgb <0.15, 0.3, 0.6> } finish { reflection 0.15 } }
plane { z, 8 pigment { checker rgb <0.8, 0.3, 0.2> rgb <0.95, 0.85, 0.5> scale 1.5 } }
sphere { <-2.4, 1, 0>, 1 pigment { rgb <0.8, 0.6, 0.3> } finish { ambient 0 diffuse 0.2 reflection 0.7 phong 0.6 phong_size 80 metallic } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.2, 0.5, 0.9> } finish { ambient 0.05 diffuse 0.3 reflection { rgb <0.9, 0.5, 0.2> } specular 0.5 roughness 0.02 } }
sphere { <2.4, 1, 0>, 1 pigment { rgb <0.7, 0.7, 0.7> } finish { ambient 0 diffuse 0.3 reflection { 0.05, 0.9 falloff 2 exponent 0.7 metallic 0.8 } specular 0.6 metallic 0.5 } }
sphere { <-1.2, 0.5, -2>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } finish { reflection { 0.5 exponent 2 } } }
sphere { <1.2, 0.5, -2>, 0.5 pigment { rgb <0.2, 0.9, 0.2> } finish { reflection 0.4 reflection_exponent 1.5 brilliance 3 } }

// The albedo forms of povray 3.7's finish: diffuse albedo (scaled by
// (brilliance + 1) / 2), phong albedo ((phong_size + 1) / 2) and specular
// albedo (by roughness), each converted when its finish block closes, so a
// finish built on a declared one keeps the declared coefficients.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 0.9, 0> angle 48 }
light_source { <-10, 20, -15> rgb 1 }
light_source { <12, 8, -10> rgb 0.3 }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.35 } finish { diffuse albedo 0.6 brilliance 1.5 } }
#declare Declared = finish { ambient 0.05 diffuse albedo 0.4 brilliance 2 phong albedo 0.2 phong_size 20 }
sphere { <-3, 1, 0>, 1 pigment { rgb <0.9, 0.5, 0.3> } finish { ambient 0.05 diffuse albedo 0.5 brilliance 3 } }
sphere { <-1, 1, 0>, 1 pigment { rgb <0.3, 0.6, 0.9> } finish { ambient 0.05 diffuse 0.5 phong albedo 0.05 phong_size 60 } }
sphere { <1, 1, 0>, 1 pigment { rgb <0.4, 0.9, 0.4> } finish { ambient 0.05 specular albedo 0.04 roughness 0.02 diffuse albedo 0.5 brilliance 0.5 } }
sphere { <3, 1, 0>, 1 pigment { rgb <0.9, 0.9, 0.5> } finish { Declared brilliance 1 phong_size 5 specular albedo 0.1 roughness 0.3 } }

// Refraction through spheres and boxes of several ior, filter tinting,
// and the interior list: a sphere inside a sphere, and a merge of two
// spheres (one interior, no inner surfaces).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 42 }
light_source { <-8, 15, -12> rgb 1 }
plane { y, 0 pigment { checker rgb <0.95, 0.95, 0.9> rgb <0.1, 0.25, 0.5> scale 0.5 } }
plane { z, 5 pigment { gradient x color_map { [0 rgb <0.9, 0.2, 0.1>] [0.5 rgb <0.95, 0.9, 0.3>] [1 rgb <0.9, 0.2, 0.1>] } scale 1.2 } finish { ambient 0.5 } }
sphere { <-2.2, 1, 0>, 1 pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } interior { ior 1.5 } no_shadow }
sphere { <0, 1, 0.3>, 1 pigment { rgbf <0.7, 0.9, 1, 0.9> } finish { ambient 0 diffuse 0 } interior { ior 1.33 } no_shadow }
sphere { <0, 1, 0.3>, 0.45 pigment { rgbt <1, 0.6, 0.6, 0.6> } finish { ambient 0.1 diffuse 0.3 } interior { ior 2.0 } no_shadow }
merge {
    sphere { <1.9, 0.9, 0>, 0.8 }
    sphere { <2.6, 0.9, -0.3>, 0.6 }
    pigment { rgbt <0.9, 1, 0.9, 0.85> }
    finish { ambient 0 diffuse 0.15 }
    interior { ior 1.2 }
    no_shadow
}
box { <-0.8, 0.01, -2.2>, <0.8, 0.4, -1.8> rotate y*15 pigment { rgbft <1, 0.8, 0.3, 0.5, 0.3> } interior { ior 1.6 } no_shadow }

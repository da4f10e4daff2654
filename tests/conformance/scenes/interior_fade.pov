// Interior fade: the power law, the exponential form (fade_power >= 1000)
// and the default power 0, with a fade colour; ior 1 so paths are straight.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 45 }
light_source { <-10, 20, -15> rgb 1 }
plane { y, 0 pigment { checker rgb <0.95, 0.95, 0.9> rgb <0.2, 0.3, 0.6> scale 0.5 } }
plane { z, 5 pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.3, 0.3, 0.3> } finish { ambient 0.6 } }
sphere { <-2.1, 1, 0>, 1 pigment { rgbt <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } interior { fade_distance 0.8 fade_power 2 fade_color <0.9, 0.3, 0.1> } no_shadow }
box { <-0.7, 0.01, -0.7>, <0.7, 1.8, 0.7> rotate y*30 pigment { rgbt <1, 1, 1, 0.9> } finish { ambient 0.02 diffuse 0.1 } interior { fade_distance 1 fade_power 1001 fade_color <0.2, 0.6, 1> } no_shadow }
sphere { <2.1, 1, 0>, 1 pigment { rgbt <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } interior { fade_distance 1.5 } no_shadow }

// Refraction-heavy: rows of glass spheres and boxes in front of a patterned wall.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 3, -10> look_at <0, 1, 0> angle 50 }
light_source { <-10, 20, -15> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb <0.2, 0.3, 0.6> } }
plane { z, 6 pigment { checker rgb <0.8, 0.3, 0.2> rgb <0.9, 0.9, 0.6> } finish { ambient 0.4 } }
#for (i, -3, 3)
  sphere { <i * 1.5, 1, -1>, 0.7 pigment { rgbf <0.95, 1, 0.95, 0.95> } finish { reflection { 0, 1 fresnel } } interior { ior 1.5 } }
  box { <-0.5, 0.01, -0.5>, <0.5, 1.2, 0.5> rotate y * (i * 20) translate <i * 1.5, 0, 1.5> pigment { rgbt <1, 0.9, 0.8, 0.8> } interior { ior 1.33 } }
#end

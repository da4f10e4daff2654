// Anti-aliasing at threshold 0.1: high-contrast edges everywhere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 0.5, 0> angle 50 }
light_source { <-10, 20, -15> rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb 0 scale 0.5 } }
#for (i, -3, 3)
  sphere { <i * 1.3, 0.6, 0>, 0.6 pigment { checker rgb <1, 0.2, 0.2> rgb <0.2, 0.2, 1> scale 0.2 } }
#end

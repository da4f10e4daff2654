#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -4> look_at <0, 0.3, 0> }
light_source { <5, 8, -6> rgb 1 }
sphere { <0, 0.5, 0>, 1 pigment { gradient x color_map { [0 rgb <1, 0.3, 0.1>] [1 rgb <0.1, 0.4, 1>] } }
         finish { specular 0.5 } translate x * clock }
plane { y, -0.5 pigment { checker rgb 0.25 rgb 0.8 } }

// A camera 10^20 units up: povray shows only the sky (nothing is seen from
// 10^7 units on), and its rays must not reach Embree (it aborts on an
// origin that large).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1e20, -3> look_at 0 }
light_source { <0, 10, -10> rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.1, 0.2, 0.5>] [1 rgb <0.8, 0.9, 1>] } } }
sphere { 0, 1 pigment { rgb 1 } }
plane { y, -1 pigment { checker rgb 1 rgb 0 } }

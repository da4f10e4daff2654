// povray 3.7's radiosity directions: a sphere under a sky whose colour
// varies quickly with the direction (a sine of x, y, z per channel), a reuse radius too
// small to reuse, so every pixel on the sphere is one new sample whose
// colour is the mean of its rays' directions around its own normal (the
// sample frame switches axis where the normal is within 0.9 of z). The
// sample takes the next 35 directions of povray's pool of 1600.
#version 3.7;
global_settings { assumed_gamma 1
  radiosity { count 35 nearest_count 1 error_bound 0.0001 recursion_limit 1
              pretrace_start 1 pretrace_end 1 low_error_factor 1
              minimum_reuse 0.00001 maximum_reuse 0.00002 } }
camera { location <0, 0, -3> look_at 0 angle 45 }
sky_sphere { pigment { average pigment_map {
  [1 function { 0.5 + 0.5 * sin(9 * x) } color_map { [0 rgb 0] [1 rgb <3, 0, 0>] }]
  [1 function { 0.5 + 0.5 * sin(9 * y) } color_map { [0 rgb 0] [1 rgb <0, 3, 0>] }]
  [1 function { 0.5 + 0.5 * sin(9 * z) } color_map { [0 rgb 0] [1 rgb <0, 0, 3>] }] } } }
sphere { 0, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }

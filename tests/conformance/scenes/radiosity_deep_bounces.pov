// A closed room lit by one light through radiosity three bounces deep
// (recursion_limit 3): red and blue walls bleed onto the white ones, a
// sphere shades the floor. Counts per pass and depth, bounds and reuse
// follow povray 3.7's rules for deeper bounces (error bound and reuse
// radius doubling per bounce, deeper samples found only near their cells).
#version 3.7;
global_settings { assumed_gamma 1
  radiosity { count 300 recursion_limit 3 nearest_count 8 error_bound 0.5
              pretrace_start 0.08 pretrace_end 0.02 } }
camera { location <0, 1.5, -2.8> look_at <0, 1, 0> angle 70 }
light_source { <0.5, 2.6, -0.5> rgb 1.2 }
#declare F = finish { ambient 0 diffuse 0.75 }
box { <-2, 0, -3>, <2, 3, 2> inverse pigment { rgb 0.85 } finish { F } }
box { <-2.01, 0, -3>, <-1.99, 3, 2> pigment { rgb <0.8, 0.15, 0.1> } finish { F } }
box { <1.99, 0, -3>, <2.01, 3, 2> pigment { rgb <0.1, 0.2, 0.8> } finish { F } }
sphere { <-0.4, 0.5, 0.3>, 0.5 pigment { rgb <0.9, 0.8, 0.3> } finish { F } }
box { <0.4, 0, -0.2>, <1.2, 1.2, 0.6> rotate y*20 pigment { rgb 0.7 } finish { F } }

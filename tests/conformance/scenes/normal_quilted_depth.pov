// A quilted normal tilts the surface by its quilt offset times 2/sqrt(3)
// of the bump size (issue 22, quilt1.pov): lights low along x and along z
// show the slope's size, with povray's default controls and with others.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 9, -2.5> look_at <0, 0, 0.2> angle 55 }
light_source { <-30, 6, 0> rgb <1, 0.55, 0.3> }
light_source { <0, 8, -30> rgb <0.3, 0.6, 1> }
#default { finish { ambient 0.05 diffuse 0.9 } }
plane { y, 0 pigment { rgb 1 } normal { quilted 0.6 scale 0.8 }
    clipped_by { box { <-4, -1, 0.1>, <-0.1, 1, 4> } } }
plane { y, 0 pigment { rgb 1 } normal { quilted 1.2 control0 0.2 control1 0.9 scale 0.7 }
    clipped_by { box { <0.1, -1, 0.1>, <4, 1, 4> } } }
plane { y, 0 pigment { rgb 1 } normal { quilted 0.4 control0 1 control1 0.1 scale <0.9, 1, 0.5> rotate y * 25 }
    clipped_by { box { <-4, -1, -4>, <-0.1, 1, -0.1> } } }
plane { y, 0 pigment { rgb 1 } normal { quilted 2 control0 0.6 control1 0.6 scale 0.6 }
    clipped_by { box { <0.1, -1, -4>, <4, 1, -0.1> } } }

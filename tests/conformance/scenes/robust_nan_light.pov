// A light at a NaN position (pow of a negative number to a fraction):
// povray renders black every surface that light shines on (diffuse > 0),
// while surfaces without diffuse keep their ambient colour and the sky its
// own. NaN rays must not reach Embree (it aborts on them).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -4> look_at <0, 0.3, 0> }
light_source { <pow(-8, 1/3), 3, -3> rgb 1 }
light_source { <3, 5, -4> rgb 0.6 }
background { rgb <0.2, 0.3, 0.6> }
sphere { 0, 1 pigment { rgb <1, 0.8, 0.2> } finish { ambient 0.4 diffuse 0 } }
sphere { <1.8, 0, 0.5>, 0.6 pigment { rgb 1 } finish { ambient 0.3 diffuse 0.6 } }
// A plane 10^7 units away is not seen (povray's maximum ray distance).
plane { z, 1e7 pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } }

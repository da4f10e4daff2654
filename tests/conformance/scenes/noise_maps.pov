// Conformance: colour-list patterns whose sub-pigments are noise patterns
// with turbulence and their own transformations.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { checker pigment { granite scale 2 } pigment { bozo turbulence 0.4 scale 0.3 } scale 1.5 } }
sphere { <-1.3, 1, 0>, 1 pigment { hexagon pigment { marble turbulence 0.8 scale 0.4 } pigment { rgb <0.2, 0.4, 0.8> } pigment { wood scale 0.1 } scale 0.3 rotate 90*x } }
sphere { <1.3, 1, 0>, 1 pigment { brick pigment { agate scale 0.5 } pigment { spotted turbulence 0.5 scale 0.2 } scale 0.2 rotate 30*y } normal { dents 0.5 scale 0.2 } }

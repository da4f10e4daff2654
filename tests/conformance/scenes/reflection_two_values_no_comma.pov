// povray reads reflection's minimum and maximum with or without a comma
// between them (`reflection { 0.0 1.0 fresnel on }` as in
// examples/gamma/gamma_showcase.pov); three spheres, each with a
// variable reflection written without the comma, over a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <3, 6, -4> rgb 1 }
plane { y, -1 pigment { checker rgb 1 rgb <1, 0.2, 0.1> } }
background { rgb <0.2, 0.4, 0.8> }
sphere { <-2.2, 0, 0>, 1 pigment { rgb 0.1 } finish { reflection { 0.1 0.9 } } }
sphere { <0, 0, 0>, 1 pigment { rgb 0.1 }
  finish { reflection { rgb 0.05 rgb <0.9, 0.6, 0.2> falloff 2 } } }
sphere { <2.2, 0, 0>, 1 pigment { rgb 0.1 } finish { reflection { 0.0 1.0 fresnel on } }
  interior { ior 1.5 } }

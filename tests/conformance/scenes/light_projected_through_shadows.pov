// projected_through: the light reaches only what lies behind the object,
// as if it came from there: a copy of the object placed in the scene does
// not darken its own projection, a box between the object and the wall
// casts a shadow, a bar between the light and the object casts none
// (lights/projected_through.pov).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <2, 3, -10> direction z look_at <-2, 2, 0> }
plane { z, 0 pigment { rgb 0.6 } finish { ambient 0.1 } }
plane { y, 0 pigment { rgb <0.5, 0.6, 0.5> } finish { ambient 0.1 } }
#declare S = union { sphere { <-1, 3, -7>, 0.5 } torus { 0.6, 0.08 rotate 90*x translate <-0.2, 2.7, -6.5> } }
object { S pigment { rgb <1, 1, 0> } }
box { <-2.5, 2.6, -3>, <-1.5, 2.8, -2.9> pigment { rgb <1, 0, 0> } }
box { <-0.6, 3.4, -8.6>, <-0.4, 3.6, -8.4> pigment { rgb <0, 0, 1> } no_image }
light_source { <0, 4, -10> rgb 2 projected_through { S } }
light_source { <5, 8, -10> rgb 0.3 }

// Conformance: polygon. Loops end where a point repeats the loop's first;
// inner loops are holes (even-odd); 2-D points lie in z = 0; 3-D points in
// a tilted plane; a last loop left open is closed (povray warns); the
// polygon is a patch, seen from both sides, and moves with its object.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -14> look_at <0, 1.5, 0> angle 50 }
light_source { <-5, 12, -10> rgb 1 }
background { rgb <0.3, 0.4, 0.6> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.6 } }
// A square frame with a square hole, and a triangle inside the hole.
polygon { 13,
  <0, 0>, <4, 0>, <4, 4>, <0, 4>, <0, 0>,
  <1, 1>, <3, 1>, <3, 3>, <1, 3>, <1, 1>,
  <1.5, 1.5>, <2.5, 1.5>, <2, 2.5>
  pigment { rgb <1, 0.4, 0.2> }
  translate <-6, 0.2, 0>
}
// A star outline (self-crossing: its centre is outside by even-odd).
polygon { 6, <0, 2>, <1.2, -1.6>, <-1.9, 0.6>, <1.9, 0.6>, <-1.2, -1.6>, <0, 2>
  pigment { rgb <1, 1, 0.3> }
  translate <0, 2.2, 0>
}
// 3-D points in a tilted plane, seen from behind after a rotation.
polygon { 5, <0, 0, 0>, <3, 0, 1>, <3, 3, 2>, <0, 3, 1>, <0, 0, 0>
  pigment { rgb <0.3, 1, 0.5> }
  rotate y*160
  translate <5, 0.5, 1>
}

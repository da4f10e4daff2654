// Rays that hit nothing see no interior media, as in povray 3.7: the
// camera sits inside a hollow half-space of media (below the plane); rays
// up to the plane see its media, rays that leave the scene see the
// background untouched. On the right, two boxes of media share their
// right face: rays leaving through it are not left inside either.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, -1, -5> look_at <0, -1.5, 0> angle 70 }
background { rgb <0, 0, 0.3> }
plane { y, 0 hollow pigment { rgbt 1 }
  interior { media { emission 0.02 absorption 0.1 } } }
box { <1, -3, -2>, <2.5, -1.5, 0> hollow pigment { rgbt 1 }
  interior { media { emission <0.2, 0, 0> } } }
box { <0.5, -2.5, -1.5>, <2.5, -1, -0.5> hollow pigment { rgbt 1 }
  interior { media { emission <0, 0.2, 0> } } }

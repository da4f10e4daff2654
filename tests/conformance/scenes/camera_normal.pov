// Camera normal: every primary ray bent by a normal pattern evaluated on
// the image plane (as in povray's example animation camera2).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 3, -8>
  look_at <0, 1, 0>
  angle 50
  normal { waves 0.2 frequency 6 phase 0.4 }
}
light_source { <5, 10, -10> color rgb 1 }
plane { y, 0 pigment { checker color rgb 1 color rgb <0.2, 0.3, 0.6> } }
sphere { <0, 1, 0>, 1 pigment { color rgb <1, 0.5, 0.2> } finish { phong 0.6 } }
box { <-3, 0, 1>, <-2, 2, 2> pigment { color rgb <0.3, 0.9, 0.4> } }

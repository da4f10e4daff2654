// hollow and fog: inside a hollow object the fog stays (the camera sits in
// a hollow sky dome); inside objects that are not hollow it is left out,
// also for rays that leave the scene from inside one (the water volume,
// an inverse plane whose inside holds the sky above the far wall).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2, -9> look_at <0, 1, 0> angle 50 }
light_source { <-8, 12, -10> rgb 1 }
fog { distance 7 rgb <0.55, 0.6, 0.7> }
sphere { 0, 200 hollow pigment { rgbt 1 } }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.25 } }
box { <-4, 0.1, -1>, <-1, 1.6, 6> pigment { rgbt <0.6, 0.8, 1, 0.8> } }
sphere { <1.5, 1.2, 1>, 1.2 pigment { rgbt <1, 0.7, 0.5, 0.7> } hollow }
plane { -z, -12 inverse pigment { rgbt 1 } translate y * 3 }

// Conformance: fog turbulence (turbulence, octaves, omega, lambda,
// turb_depth) in a constant fog and a ground fog.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1, 4> angle 60 }
light_source { <-5, 9, -7> color rgb 1 }
background { rgb <0.3, 0.4, 0.7> }

plane { y, 0 pigment { checker rgb <0.2, 0.3, 0.2>, rgb <0.8, 0.8, 0.6> } }
#for (I, 0, 6)
  sphere { <-6 + 2 * I, 1, 2 + 3 * I>, 1 pigment { rgb <1, 0.4, 0.2> } }
#end
box { <-20, 0, 30>, <20, 8, 31> pigment { gradient y color_map { [0 rgb 1] [1 rgb <0.2, 0.6, 1>] } scale 8 } }
fog { distance 12 color rgbf <0.8, 0.85, 0.9, 0.2> turbulence <1.5, 2, 1.2> octaves 4 omega 0.6 lambda 2.5 turb_depth 1 }
fog { fog_type 2 distance 3 fog_offset 0.3 fog_alt 0.6 color rgb <0.6, 0.7, 0.5> turbulence 2 turb_depth 0.8 }

// Light totally reflected inside a fading interior fades over its way as
// refracted light does: the block's edges, seen through several internal
// reflections, are as dim as its faces (povray 3.7, measured; frameray
// showed them bright white).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 15 }
camera { location <0, 1, -4> right x*image_width/image_height look_at <0, 1, 0> angle 40 }
background { rgb 1 }
box { <-0.5, 0.1, -0.5>, <0.5, 1.8, 0.5> rotate 30*y
  texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } }
  interior { ior 1.5 fade_distance 2 fade_power 1 } }

// Total internal reflection under a layered texture: the mirrored ray
// takes what every layer's reflection left, not what the lowest layer's
// (none) left, so a fresnel top layer is not counted twice (povray 3.7,
// measured: frameray's edges were up to 98/255 too bright).
#version 3.6;
global_settings { assumed_gamma 1.0 max_trace_level 15 }
camera { location <0, 1, -4> right x*image_width/image_height look_at <0, 1, 0> angle 40 }
background { rgb <0.2, 0.3, 0.6> }
light_source { <500, 50, -5> rgb 1 }
box { <-0.5, 0.1, -0.5>, <0.5, 1.8, 0.5> rotate 30*y
  pigment { rgbf 0.9 }
  texture { pigment { rgbf <0.98, 1, 0.98, 1> }
    finish { specular 1 roughness 0.001 ambient 0 diffuse 0 reflection { 0, 1 fresnel } } }
  interior { ior 1.5 } }

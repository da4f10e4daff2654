// Reflections inside a fading glass block (povray 3.7, measured): the part
// of a reflection that varies with the angle fades as the light there
// does and its minimum does not (left: reflection {0.2, 1 fresnel});
// a finish that conserves energy keeps its reflection whole (right).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 15 }
camera { location <0, 1, -4.5> right x*image_width/image_height look_at <0, 1, 0> angle 45 }
background { rgb <0.2, 0.3, 0.6> }
light_source { <500, 50, -5> rgb 1 }
box { <-0.5, 0.1, -0.5>, <0.5, 1.8, 0.5> rotate 30*y translate -0.8*x
  texture { pigment { rgbf <0.98, 1, 0.98, 1> } finish { ambient 0 diffuse 0 reflection { 0.2, 1 fresnel } } }
  interior { ior 1.5 fade_distance 2 fade_power 2 } }
box { <-0.5, 0.1, -0.5>, <0.5, 1.8, 0.5> rotate 30*y translate 0.8*x
  texture { pigment { rgbf <0.98, 1, 0.98, 1> }
    finish { ambient 0 diffuse 0 reflection { 0.2, 1 fresnel } conserve_energy } }
  interior { ior 1.5 fade_distance 2 fade_power 2 } }

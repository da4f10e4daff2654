// Radiosity under an emissive sky: the floor gathers light from a sky that
// is white above 30 degrees elevation and orange below (cosine-weighted: a
// share of 0.75 and 0.25), turned partly grey by gray_threshold and scaled by
// brightness; ambient is ignored under radiosity in a 3.7 scene.
#version 3.7;
global_settings {
  assumed_gamma 1
  radiosity { count 60 error_bound 0.8 gray_threshold 0.4 brightness 1.3 recursion_limit 1
              pretrace_start 0.1 pretrace_end 0.05 }
}
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
sphere { 0, 1 hollow
  texture { pigment { gradient y color_map { [0.5 rgb <1, 0.4, 0.1>] [0.5 rgb 1] } }
            finish { diffuse 0 ambient 0 emission 1 } }
  scale 10000 }
plane { y, 0 texture { pigment { rgb <0.9, 0.8, 0.6> } finish { diffuse 0.6 ambient 0.5 } } }
box { <-1.5, -1, -0.5>, <1.5, 0.001, 0.5> texture { pigment { rgb <0.3, 0.5, 0.9> } finish { diffuse 0.9 ambient 1 } } }

// average: every entry of a pigment_map or texture_map, weighted by its
// value.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
sphere { <-1.1, 0.9, 0>, 0.9
  pigment { average pigment_map {
    [1 gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb 0] } scale 0.3]
    [2 gradient y color_map { [0 rgb <0, 0, 1>] [1 rgb 1] } scale 0.4]
    [1 rgb <0, 1, 0>]
  } }
}
sphere { <1.1, 0.9, 0.3>, 0.9
  texture { average texture_map {
    [1 pigment { rgb <1, 0.5, 0> } finish { phong 0.9 phong_size 60 }]
    [1 pigment { rgb <0.2, 0.2, 1> } normal { bumps 0.7 scale 0.1 }]
  } }
}
plane { y, 0 pigment { rgb 0.6 } }

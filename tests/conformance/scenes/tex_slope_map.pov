// slope_map: the pattern value becomes a height by cubic interpolation
// between entries of height and slope; with bump sizes and wave types.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
#declare SM_Ridge = slope_map { [0 <0, 1>] [0.5 <1, 1>] [0.5 <1, -1>] [1 <0, -1>] }
sphere { <-1.1, 0.9, 0>, 0.9
  pigment { rgb <1, 0.8, 0.6> } finish { phong 0.6 }
  normal { gradient y 1.5 slope_map { SM_Ridge } scale 0.3 }
}
sphere { <1.1, 0.9, 0.3>, 0.9
  pigment { rgb <0.6, 0.8, 1> } finish { specular 0.5 }
  normal { wood slope_map { [0 <0, 0>] [0.3 <0.2, 2>] [0.7 <1, 0>] [1 <0.5, -1>] } bump_size 0.8 scale 0.2 }
}
plane { y, 0
  pigment { rgb 0.8 }
  normal { onion slope_map { [0 <0, 0>] [0.5 <1, 0>] [1 <0, 0>] } sine_wave scale 0.4 }
}

// image_pattern as a colour-mapped pattern (grey value and use_alpha,
// with a wave type and frequency) and as a normal pattern.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.2, 0> angle 50 }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, -1
  pigment {
    image_pattern { png "image_heights.png" interpolate 2 }
    color_map { [0 rgb <0.1, 0.2, 0.5>] [0.5 rgb <0.9, 0.8, 0.3>] [1 rgb <1, 1, 1>] }
    rotate x*90 scale 2
  }
}
box { <0, 0, 0>, <1, 1, 0.1>
  pigment {
    image_pattern { png "image_alpha.png" use_alpha }
    color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] }
  }
  scale 1.3 translate <-2.2, -0.6, 0>
}
box { <0, 0, 0>, <1, 1, 0.1>
  pigment {
    image_pattern { png "image_grid.png" }
    color_map { [0.3 rgb <1, 1, 1>] [0.3 rgb <0.1, 0.1, 0.1>] [0.7 rgb <0.2, 0.8, 0.3>] }
    frequency 2 triangle_wave
  }
  scale 1.3 translate <-0.65, -0.6, 0>
}
sphere { <1.5, 0, 0>, 0.8
  pigment { rgb <0.9, 0.6, 0.5> }
  normal { image_pattern { png "image_heights.png" interpolate 2 } bump_size 1.5 scale 0.5 }
}

// A declared layered texture transformed where it is used: every layer
// moves (povray 3.7, measured; the woodbox example's floor).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <-5, 10, -15> look_at 0 angle 45 }
light_source { <-10, 20, -15> rgb 1 }
#declare Layers =
  texture { pigment { checker rgb <0.5, 0.5, 0.5> rgb <0.2, 0.3, 0.4> } }
  texture { pigment { gradient x color_map { [0 rgbf <0.5, 0.26, 0.12, 0.1>] [1 rgbf <0.55, 0.28, 0.1, 0.7>] } } }
  texture { pigment { gradient z color_map { [0 rgbf <0.5, 0.26, 0.12, 0.1>] [1 rgbf <0.55, 0.28, 0.1, 0.9>] } } finish { reflection 0.1 } }
plane { y, 0 texture { Layers scale 1.7 rotate y * 35 translate x * 0.3 } }
sphere { <0, 1.5, 0>, 1.5 texture { Layers scale 0.5 rotate <10, 0, 15> } }

// Conformance: a rainbow with arc_angle and falloff_angle over a sky and
// in front of distant objects, with a second, fainter rainbow outside it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -8> look_at <0, 4, 10> angle 90 }
light_source { <-5, 10, -8> color rgb 1 }
plane { y, 0 pigment { rgb <0.3, 0.5, 0.2> } }
box { <-6, 0, 30>, <-2, 12, 34> pigment { rgb <0.6, 0.6, 0.6> } }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.6, 0.7, 0.9>] [1 rgb <0.1, 0.2, 0.6>] } } }
rainbow {
  angle 42.5
  width 5
  distance 60
  direction <-0.2, -0.2, 1>
  arc_angle 120
  falloff_angle 30
  color_map {
    [0.0 rgbt <1, 0, 0, 1>]
    [0.1 rgbt <1, 0, 0, 0.6>]
    [0.3 rgbt <1, 1, 0, 0.6>]
    [0.5 rgbt <0, 1, 0, 0.6>]
    [0.7 rgbt <0, 0, 1, 0.6>]
    [0.9 rgbft <0.6, 0, 1, 0.5, 0.6>]
    [1.0 rgbt <0.6, 0, 1, 1>]
  }
}
rainbow {
  angle 52
  width 3
  direction <-0.2, -0.2, 1>
  up <0.2, 1, 0>
  color_map { [0 rgbt <0.6, 0, 1, 1>] [0.5 rgbt <1, 1, 1, 0.8>] [1 rgbt <1, 0, 0, 1>] }
}

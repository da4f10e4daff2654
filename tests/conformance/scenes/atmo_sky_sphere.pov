// Conformance: a sky_sphere with one colour-mapped gradient pigment seen
// above a floor, rotated.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 2, 0> angle 80 }
light_source { <-5, 10, -8> color rgb 1 }
plane { y, 0 pigment { rgb <0.4, 0.35, 0.3> } }
sphere { <0, 1, 2>, 1 pigment { rgb <0.9, 0.9, 0.9> } }
sky_sphere {
  pigment {
    gradient y
    color_map { [0 rgb <1, 0.9, 0.7>] [0.3 rgb <0.3, 0.5, 1>] [1 rgb <0.05, 0.1, 0.4>] }
  }
  rotate z * 15
}

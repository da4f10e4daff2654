// Conformance: pre-3.7 sky_sphere and background rules (#version 3.6):
// the background keeps its full colour and layers attenuate each other by
// filter and transmit.
#version 3.6;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, 0> look_at <0, 0.3, 1> angle 100 }
background { rgbt <0.2, 0.7, 0.3, 0.5> }
sky_sphere {
  pigment {
    gradient y
    color_map { [0 rgbf <0.9, 0.8, 0.6, 0.4>] [0.5 rgbt <0.2, 0.4, 0.9, 0.6>] [1 rgb <0.05, 0.05, 0.3>] }
  }
  pigment { gradient x frequency 2 color_map { [0 rgbt <1, 1, 1, 1>] [1 rgbt <1, 0.5, 0.5, 0.3>] } }
  emission 0.9
}
sphere { <0.8, -0.6, 3>, 0.4 pigment { rgb <0.9, 0.9, 0.2> } finish { ambient 1 diffuse 0 } }

// Conformance: a sky_sphere with several layers (the later ones in front:
// a transmitting cloud band over a gradient, a filtering tint), emission,
// transformations including a translation, over a background colour that
// shows through the transparent parts.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, 0> look_at <0, 0.3, 1> angle 100 }
background { rgb <0.8, 0.1, 0.1> }
sky_sphere {
  pigment {
    gradient y
    color_map { [0 rgb <0.9, 0.8, 0.6>] [0.5 rgbt <0.2, 0.4, 0.9, 0.5>] [1 rgb <0.05, 0.05, 0.3>] }
  }
  pigment {
    gradient x frequency 3
    color_map { [0 rgbt <1, 1, 1, 1>] [0.5 rgbt <1, 1, 1, 0.2>] [1 rgbt <1, 1, 1, 1>] }
  }
  pigment { checker rgbf <1, 0.6, 0.6, 0.7> rgbt <1, 1, 1, 1> scale 0.25 }
  emission rgb <1.2, 1, 0.9>
  scale <1, 0.8, 1>
  rotate y * 20
  translate <0.1, 0, 0>
}
sphere { <0.8, -0.6, 3>, 0.4 pigment { rgb <0.9, 0.9, 0.2> } finish { ambient 1 diffuse 0 } }

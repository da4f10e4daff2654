// Conformance: shadows through interiors with fade_distance. At the
// default fade_power 0 a camera ray through the sphere passes half the
// light (1 / (1 + (d / D)^0)), but a shadow ray is not faded at all; at
// powers 1 and 2 both fade by the chord's length. The light comes from
// the side so each sphere and its shadow show apart.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -100> right 80 * 4/3 * x up 80 * y look_at 0 }
plane { -z, -20 pigment { checker rgb 1 rgb <0.6, 0.8, 1> scale 5 } finish { ambient 0.1 diffuse 0.9 } }
#macro S(X, P)
  sphere { <X, 8, 0>, 9
    pigment { rgbt <1, 0.9, 0.7, 0.85> }
    finish { ambient 0 diffuse 0 }
    interior { fade_distance 12 fade_power P }
  }
#end
S(-32, 0) S(0, 1) S(32, 2)
light_source { <4000, -6000, -10000> color rgb 1 }

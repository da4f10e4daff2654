// Conformance: in a #version 3.6 scene a filtering pigment's own colour
// is weighed by 1 - filter * max(colour) - transmit (3.7: 1 - filter -
// transmit): grey, tinted and mixed filter/transmit panes over a lit
// checker, and a layered texture whose top layer filters.
#version 3.6;
global_settings { assumed_gamma 2.2 }
camera { location <0, 1, -8> look_at <0, 0.5, 0> angle 60 }
light_source { <-4, 8, -10> rgb 1 }
plane { z, 3 pigment { checker rgb <0.9, 0.85, 0.5> rgb <0.2, 0.4, 0.6> } }
#macro Pane(X, C)
  box { <-0.8, -1, -0.05>, <0.8, 1.5, 0.05> pigment { C } translate <X, 0, 0> }
#end
Pane(-3, rgbf <0.5, 0.5, 0.5, 1>)
Pane(-1, rgbf <0.9, 0.4, 0.3, 0.8>)
Pane(1, rgbft <0.7, 0.7, 0.575, 0.5, 0.25>)
sphere { <3, 0.3, 0>, 1
  texture { pigment { rgb <0.85, 0.85, 0.45> } }
  texture { pigment { gradient y color_map { [0 rgbf 1] [1 rgbt <0.4, 0.4, 0.15, 0.5>] } scale 0.5 } }
}

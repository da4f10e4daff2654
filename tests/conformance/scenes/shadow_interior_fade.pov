// Shadow rays through fading interiors: the light is faded over the
// distance between entering and leaving each fading object (glass.inc's
// I_Glass interiors); a clear pane in front of one shadow, a second fading
// object seen in front of another, and an exponential fade.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -30> look_at 0 right 6 * x up 4.5 * y }
light_source { <-30, 40, -60> rgb 1 }
background { rgb <0.25, 0.3, 0.4> }
plane { z, 3 pigment { checker rgb 0.9 rgb 0.5 scale 1.25 } }
sphere { 0, 1 pigment { rgbf <1, 1, 1, 0.9> } finish { diffuse 0.1 specular 0.6 roughness 0.005 }
  interior { ior 1.5 fade_distance 1 fade_power 2 } translate <-1.6, 0.6, 0> }
sphere { 0, 0.7 pigment { rgbf <1, 1, 1, 1> } interior { ior 1.0 fade_distance 1.0 fade_power 2 } translate <1.2, 1.2, 0> }
box { <-0.3, -2.2, -2>, <1.2, -0.6, -1.9> pigment { rgbf <1, 1, 1, 0.95> } }
box { <1.6, -2.2, -2>, <2.8, -0.6, -1.9> pigment { rgbf <1, 1, 1, 0.95> } interior { fade_distance 0.5 fade_power 2 } }
box { <-2.8, -2.1, -0.5>, <-1.6, -1.1, 0.5> pigment { rgbf <1, 0.9, 0.8, 1> }
  interior { ior 1.0 fade_distance 1 fade_power 1001 fade_color <0.2, 0.4, 0.8> } }

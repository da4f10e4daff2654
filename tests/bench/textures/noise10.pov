// Issue 7's texture benchmark: ten tiles filling the frame, each with a
// different noise-based texture with turbulence, so that every camera ray
// evaluates povray's noise (several octaves) once or more:
// granite, marble, wood, bozo, agate, spotted with a bumps normal,
// wrinkles, crackle, leopard and onion with turbulence, and a dents normal.
// Goal: frameray's time at most half of povray's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 10 * x up 7.5 * y }
light_source { <-20, 30, -40> rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
// Tile I: the box <-1, -1.875, 0>, <1, 1.875, 1> moved to its cell.
#macro At(I) translate <-4 + 2 * mod(I, 5), (I < 5 ? 1.875 : -1.875), 0> #end
box { <-1, -1.875, 0>, <1, 1.875, 1>
  pigment { granite turbulence 0.4 color_map { [0 rgb <0.9, 0.7, 0.6>] [0.5 rgb <0.5, 0.3, 0.3>] [1 rgb 0.1] } scale 0.8 }
  finish { phong 0.5 } At(0) }
box { <-1, -1.875, 0>, <1, 1.875, 1>
  pigment { marble turbulence 1.2 octaves 6 color_map { [0 rgb 0.95] [0.8 rgb <0.7, 0.7, 0.8>] [1 rgb <0.2, 0.2, 0.4>] } scale 0.6 }
  finish { specular 0.4 } At(1) }
box { <-1, -1.875, 0>, <1, 1.875, 1>
  pigment { wood turbulence 0.1 octaves 4 color_map { [0 rgb <0.8, 0.5, 0.25>] [0.7 rgb <0.6, 0.35, 0.15>] [1 rgb <0.4, 0.2, 0.1>] } scale 0.15 rotate <80, 10, 0> }
  At(2) }
box { <-1, -1.875, 0>, <1, 1.875, 1>
  pigment { bozo turbulence 0.65 octaves 6 omega 0.7 lambda 2 color_map { [0 rgb <0.3, 0.4, 0.9>] [0.5 rgb 1] [1 rgb 0.6] } scale 0.5 }
  At(3) }
box { <-1, -1.875, 0>, <1, 1.875, 1>
  pigment { agate agate_turb 0.6 color_map { [0 rgb <0.8, 0.4, 0.1>] [0.5 rgb <0.9, 0.8, 0.6>] [1 rgb <0.3, 0.1, 0.05>] } scale 0.7 }
  At(4) }
box { <-1, -1.875, 0>, <1, 1.875, 1>
  pigment { spotted turbulence 0.5 color_map { [0 rgb <0.2, 0.6, 0.2>] [1 rgb <0.9, 0.9, 0.5>] } scale 0.3 }
  normal { bumps 0.6 turbulence 0.3 scale 0.1 }
  At(5) }
box { <-1, -1.875, 0>, <1, 1.875, 1>
  pigment { rgb <0.8, 0.6, 0.5> }
  normal { wrinkles 0.8 turbulence 0.4 scale 0.3 }
  finish { phong 0.6 } At(6) }
box { <-1, -1.875, 0>, <1, 1.875, 1>
  pigment { crackle turbulence 0.3 color_map { [0 rgb 0.1] [0.08 rgb 0.1] [0.12 rgb <0.9, 0.8, 0.7>] [1 rgb <0.7, 0.6, 0.5>] } scale 0.3 }
  At(7) }
box { <-1, -1.875, 0>, <1, 1.875, 1>
  pigment { leopard turbulence 0.6 color_map { [0 rgb <0.9, 0.7, 0.2>] [0.12 rgb <0.9, 0.7, 0.2>] [0.2 rgb 0.1] [1 rgb 0.1] } scale 0.1 }
  At(8) }
box { <-1, -1.875, 0>, <1, 1.875, 1>
  pigment { onion turbulence 0.8 octaves 5 lambda 2.5 color_map { [0 rgb <0.5, 0.1, 0.6>] [1 rgb <0.9, 0.8, 1>] } scale 0.4 }
  normal { dents 0.5 turbulence 0.2 scale 0.2 }
  At(9) }

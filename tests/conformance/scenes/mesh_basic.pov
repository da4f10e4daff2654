#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -2> color rgb 0.4 }
background { color rgb <0.2, 0.25, 0.3> }
// A flat-shaded pyramid and a smooth-shaded one side by side.
#declare Apex = <0, 1.2, 0>;
#declare Flat = mesh {
  triangle { <-1, 0, -1>, <1, 0, -1>, Apex }
  triangle { <1, 0, -1>, <1, 0, 1>, Apex }
  triangle { <1, 0, 1>, <-1, 0, 1>, Apex }
  triangle { <-1, 0, 1>, <-1, 0, -1>, Apex }
}
object { Flat translate <-1.3, 0, 0> pigment { color rgb <1, 0.6, 0.2> } }
#declare Smooth = mesh {
  smooth_triangle { <-1, 0, -1>, <-1, 0.5, -1>, <1, 0, -1>, <1, 0.5, -1>, Apex, <0, 1, 0> }
  smooth_triangle { <1, 0, -1>, <1, 0.5, -1>, <1, 0, 1>, <1, 0.5, 1>, Apex, <0, 1, 0> }
  smooth_triangle { <1, 0, 1>, <1, 0.5, 1>, <-1, 0, 1>, <-1, 0.5, 1>, Apex, <0, 1, 0> }
  smooth_triangle { <-1, 0, 1>, <-1, 0.5, 1>, <-1, 0, -1>, <-1, 0.5, -1>, Apex, <0, 1, 0> }
}
object { Smooth translate <1.3, 0, 0> pigment { color rgb <0.3, 0.7, 1> } finish { phong 0.6 } }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.5 } }

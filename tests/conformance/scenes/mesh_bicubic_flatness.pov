#version 3.7;
global_settings { assumed_gamma 1.0 }
// bicubic_patch with flatness 0.01, 0.1 and 0.5: sub-patches stop splitting
// once their control net lies within flatness of the plane of three corners,
// measured after the transform (povray moves the control points). povray
// leaves cracks where neighbours stop at different depths; so does this.
camera { location <0, 4, -6> look_at <0, 0.3, 0> angle 45 }
light_source { <-3, 6, -4> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
#macro P(F)
bicubic_patch { type 1 flatness F u_steps 4 v_steps 4
  <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>,
  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,
  <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>
  translate <-1.5, -1.5, 0> scale 0.6 rotate x * 60 }
#end
#declare A = P(0.01)
#declare B = P(0.1)
#declare C = P(0.5)
object { A translate <-2, 0, 0> pigment { checker color rgb 1 color rgb <1, 0.3, 0.2> scale 0.2 } }
object { B pigment { checker color rgb 1 color rgb <0.2, 0.8, 0.3> scale 0.2 } }
object { C translate <2, 0, 0> pigment { checker color rgb 1 color rgb <0.2, 0.3, 1> scale 0.2 } }

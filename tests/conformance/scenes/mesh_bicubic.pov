#version 3.7;
global_settings { assumed_gamma 1.0 }
// bicubic_patch type 0 and type 1 with various u_steps / v_steps: povray
// draws 2^u_steps x 2^v_steps sub-patches as two smooth triangles each.
camera { location <0, 4, -6> look_at <0, 0.3, 0> angle 45 }
light_source { <-3, 6, -4> color rgb 1 }
light_source { <4, 3, -1> color rgb 0.3 }
background { color rgb <0.3, 0.4, 0.6> }
#declare Points = array[16] {
  <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>,
  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,
  <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2> }
#macro Patch(T, U, V)
  bicubic_patch { type T u_steps U v_steps V
    Points[0], Points[1], Points[2], Points[3], Points[4], Points[5], Points[6], Points[7],
    Points[8], Points[9], Points[10], Points[11], Points[12], Points[13], Points[14], Points[15]
    translate <-1.5, -1.5, 0> scale 0.5 rotate x * 60 }
#end
#declare P1 = Patch(0, 3, 3)
#declare P2 = Patch(1, 4, 2)
#declare P3 = Patch(1, 1, 1)
object { P1 translate <-1.8, 0, 1> pigment { color rgb <1, 0.6, 0.3> } }
object { P2 translate <0, 0, 1> pigment { color rgb <0.4, 1, 0.5> } finish { phong 0.7 } }
object { P3 translate <1.8, 0, 1> pigment { color rgb <0.5, 0.7, 1> } }
bicubic_patch { type 1 u_steps 2 v_steps 3
  <0, 0, 0>, <1, 1, 0>, <2, -1, 0>, <3, 0, 0>,
  <0, 1, 1>, <1, 2, 1>, <2, 0, 1>, <3, 1, 1>,
  <0, -1, 2>, <1, 0, 2>, <2, -2, 2>, <3, -1, 2>,
  <0, 0, 3>, <1, 1, 3>, <2, -1, 3>, <3, 0, 3>
  scale 0.5 translate <-0.75, -0.6, -2.2>
  pigment { checker color rgb 1 color rgb <1, 0.2, 0.2> scale 0.25 }
}

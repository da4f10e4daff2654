#version 3.7;
global_settings { assumed_gamma 1.0 }
// Eight frames: a red sphere circling a blue box over a checkered plane.
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <4, 6, -5> color rgb 1 }
background { color rgb <0, 0.8, 0> }
plane { y, 0 pigment { checker color rgb 1 color rgb 0.3 } }
box { -0.5, 0.5 translate y*0.5 pigment { color rgb <0.1, 0.2, 0.9> } }
sphere { <1.6, 0.5, 0>, 0.5 rotate y*clock*360 pigment { color rgb <0.9, 0.1, 0.1> } }
// Declare=FailAt=N makes frame N fail (the contact sheet marks it).
#ifdef (FailAt) #if (frame_number = FailAt) #error "frame failed on purpose" #end #end

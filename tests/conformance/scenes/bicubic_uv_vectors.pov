// Conformance: bicubic_patch uv_vectors: the (u, v) that uv_mapping gives
// the patch's four corners, blended bilinearly (the example portfolio's
// allobjects.pov writes the default ones). A flat patch with a stretched
// and a skewed set, and one with the defaults written out. The patches'
// uv_mapping is an object modifier before the pigment, as allobjects has it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -2.2> look_at <0, 0, 0.4> angle 75 }
light_source { <-3, 8, -4> rgb 1 }
background { rgb 0.2 }
#macro Patch(UV0, UV1, UV2, UV3)
  bicubic_patch {
    type 1 flatness 0 u_steps 3 v_steps 3
    uv_vectors UV0 UV1 UV2 UV3
    <0,0,0> <1,0,0> <2,0,0> <3,0,0>
    <0,0,1> <1,0.6,1> <2,0.6,1> <3,0,1>
    <0,0,2> <1,0.6,2> <2,0.6,2> <3,0,2>
    <0,0,3> <1,0,3> <2,0,3> <3,0,3>
    uv_mapping
    pigment { checker rgb <1, 0.5, 0.2> rgb <0.2, 0.4, 1> scale 0.25 }
    scale 0.6
  }
#end
object { Patch(<0,0>, <1,0>, <1,1>, <0,1>) translate <-3, 0, -0.5> }
object { Patch(<0,0>, <2,0>, <2,1>, <0,1>) translate <-0.9, 0, -0.5> }
object { Patch(<0,0>, <1,0.5>, <1.5,1.5>, <0,1>) translate <1.2, 0, -0.5> }

#version 3.7;
global_settings { assumed_gamma 1.0 }
// The height field of mesh_hf_png, steeper, smooth (povray's normals:
// quadrant normals per sample, blended bilinearly after the transform)
// and with water_level: no hit below y = 0.45 in object space.
camera { location <0, 2.2, -2.6> look_at <0, 0.1, 0> angle 45 }
light_source { <-3, 6, -4> color rgb 1 }
light_source { <4, 3, -1> color rgb 0.3 }
background { color rgb <0.3, 0.4, 0.6> }
height_field {
  png "mesh_hf_bumps.png" smooth water_level 0.45
  translate <-0.5, 0, -0.5>
  scale <2.4, 1.4, 1.8>
  pigment { gradient y color_map { [0 color rgb <0.2, 0.5, 0.1>] [0.5 color rgb <0.6, 0.5, 0.3>] [1 color rgb 1] } scale 1.4 }
}
plane { y, 0.5 pigment { color rgb <0.1, 0.3, 0.8> } }

// pigment_map entries are pigment bodies (colours, identifiers, patterns
// with their own modifiers); declared color_map and pigment_map
// identifiers; transformations move the map and its pigments.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
#declare CM_Fire = color_map { [0 rgb <1, 1, 0>] [0.5 rgb <1, 0.3, 0>] [1 rgb <0.3, 0, 0>] }
#declare P_Stripes = pigment { gradient y color_map { CM_Fire } scale 0.2 }
#declare PM_Mix = pigment_map {
  [0.2 P_Stripes]
  [0.5 checker rgb 1, rgb <0, 0.3, 0.8> scale 0.15]
  [0.8 rgb <0.1, 0.7, 0.2>]
}
sphere { <-1.1, 0.9, 0>, 0.9
  pigment { gradient x pigment_map { PM_Mix } scale 0.8 rotate 30 * z }
}
sphere { <1.1, 0.9, 0.3>, 0.9
  pigment {
    bozo turbulence 0.3
    pigment_map {
      [0.3 P_Stripes rotate 90 * x]
      [0.7 granite color_map { [0 rgb 0.1] [1 rgb 0.9] } scale 0.4]
    }
    scale 0.6
  }
  finish { phong 0.5 }
}
plane { y, 0
  pigment { checker pigment { radial frequency 6 color_map { CM_Fire } }, pigment { rgb 0.7 } scale 1.2 }
}

// A cavity cut into glass by a CSG without an interior of its own is one
// region of air: a ray that enters it through the sphere's face leaves
// it through the box's face back into the glass (povray 3.7, measured:
// the CSG's primitives share one default interior). frameray took the box
// face for the way into yet another region and did not bend back.
#version 3.6;
global_settings { assumed_gamma 1.0 max_trace_level 15 }
camera { location <0, 1, -4> right x*image_width/image_height look_at <0, 1, 0> angle 40 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.3, 0.05, 0.15>] [1 rgb 1] } translate -0.1*y } }
light_source { <500, 50, -5> rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb <0, 0, 1> scale 0.5 } }
difference {
  box { <-0.8, 0.2, -0.5>, <0.8, 1.8, 0.5>
    texture { pigment { rgbf <0.98, 1, 0.98, 1> }
      finish { specular 1 roughness 0.001 ambient 0 diffuse 0 reflection { 0, 1 fresnel } } }
    interior { ior 1.5 } }
  intersection { sphere { <0, 1, 0>, 0.4 } box { <0, 0, -1>, <1, 2, 1> rotate 20*y translate -1.1*x }
    texture { pigment { rgbt <0.9, 0.9, 0.6, 0.6> } finish { reflection 0.3 } } }
  rotate 30*y
}

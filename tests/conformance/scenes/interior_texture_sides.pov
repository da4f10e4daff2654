// Conformance: interior_texture colours the inner side of a surface (where
// the outward normal faces away from the viewer): the inside of clipped
// spheres, inherited from a union, and the back of a plane; it moves with
// the object's transformations.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 6, -4> rgb 1 }
background { rgb 0.2 }
sphere { <-1.3, 0, 0>, 1
  texture { pigment { rgb <1, 0.2, 0.2> } }
  interior_texture { pigment { checker rgb <0.2, 1, 0.2> rgb <0, 0.4, 0> scale 0.25 } }
  clipped_by { plane { y, 0.3 } }
  rotate z*10
}
union {
  sphere { <1.3, 0, 0>, 1 clipped_by { plane { y, 0.3 } } }
  texture { pigment { rgb <1, 0.2, 0.2> } }
  interior_texture { pigment { rgb <0.2, 0.2, 1> } finish { phong 0.8 } }
}
plane { z, 2
  texture { pigment { rgb 1 } }
  interior_texture { pigment { rgb <1, 1, 0> } }
  rotate x*80 translate -y*1.5
}

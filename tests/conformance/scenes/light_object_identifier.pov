// Conformance: a declared light_source placed with object { LIGHT }, moved
// by the object's transformations with its looks_like shape (the example
// advanced/desk/desk.pov places its lamp's tube this way), at the top
// level and inside a union.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.3, 0> angle 55 }
background { rgb 0.05 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.6 } }
sphere { <-1.2, 0.7, 0.5>, 0.7 pigment { rgb <1, 0.5, 0.3> } }
box { <0.5, 0, 0>, <1.7, 1.2, 1> pigment { rgb <0.4, 0.6, 1> } }
#declare Lamp = light_source { <0, 0, 0> rgb <1, 0.95, 0.8>
  looks_like { sphere { 0, 0.15 pigment { rgb 1 } finish { ambient 1 diffuse 0 } } }
}
object { Lamp translate <-2, 2.2, -1.5> }
union {
  object { Lamp scale 0.5 }
  cylinder { <0, -0.5, 0>, <0, -0.1, 0>, 0.05 pigment { rgb <0.3, 1, 0.3> } }
  translate <1.5, 2.5, -1>
}

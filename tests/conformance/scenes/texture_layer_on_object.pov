// A texture given to an object that has one already lies on top of it as
// a new layer that starts from the default texture (povray 3.7, measured):
// the half-transparent green shows the red below it, a finish-only layer
// is an opaque black default pigment, and `pigment { } texture { }`
// layers the texture over the grey (advanced/glasschess.pov's pieces).
// A material's texture layers the same way; loose pigment and finish
// items still edit the top layer.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -9> look_at 0 angle 50 }
background { rgb <0.1, 0.2, 0.5> }
light_source { <5, 5, -5> rgb 1 }
#declare Red = sphere { 0, 0.9 texture { pigment { rgb <1, 0, 0> } finish { phong 1 ambient 0.3 } } }
object { Red texture { pigment { rgbt <0, 1, 0, 0.5> } } translate <-3, 1.1, 0> }
object { Red texture { finish { phong 1 } } translate <-1, 1.1, 0> }
object { Red material { texture { pigment { rgbt <0, 1, 0, 0.5> } } } translate <1, 1.1, 0> }
object { Red pigment { rgbt <0, 1, 0, 0.5> } translate <3, 1.1, 0> }
sphere { 0, 0.9 pigment { rgbf 0.9 }
  texture { pigment { rgbf <0.98, 1, 0.98, 1> } finish { ambient 0 diffuse 0 } }
  translate <-2, -1.1, 0> }
sphere { 0, 0.9 pigment { rgb <1, 0, 0> } finish { phong 1 ambient 0.3 }
  texture { pigment { rgbt <0, 1, 0, 0.5> } }
  translate <0, -1.1, 0> }
sphere { 0, 0.9 texture { pigment { rgb <1, 0, 0> } } texture { pigment { rgbt <0, 0, 1, 0.5> } }
  texture { pigment { rgbt <0, 1, 0, 0.7> } }
  translate <2, -1.1, 0> }

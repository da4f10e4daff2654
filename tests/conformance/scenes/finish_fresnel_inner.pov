// Fresnel reflection inside glass. povray 3.7 reflects a ray leaving an
// object by the fresnel ratio of the two iors only when the object is the
// one region the ray is in; inside others too (here the left pair sits in
// a box of air, ior 1, that holds them both) the ratio it uses is 1 and
// nothing is reflected from inside. Both cases side by side. (Boxes, where
// total internal reflection mixes in, still differ: a rotated glass box in
// the air matches 0.9967, so they are left out here.)
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 ambient_light 0 }
camera { location <0, 0.5, -6> look_at <0, 0, 0> angle 50 }
background { rgb <0.2, 0.4, 0.6> }
plane { -z, -8 pigment { checker rgb <0.6, 0.6, 0.9> rgb <0.2, 0.2, 0.4> } finish { emission 1 diffuse 0 } }
#declare Glass = material {
  texture { pigment { rgbt <1, 0.8, 0.6, 0.5> } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel } } }
  interior { ior 1.5 }
}
// In the air alone: inner reflections show.
sphere { <1.4, 0.6, 0>, 1 material { Glass } }
sphere { <1.4, -1.3, 0>, 0.6 material { Glass } scale <1.3, 1, 1> }
// Inside an invisible box of air as well: no fresnel reflection from inside.
box { <-3.2, -2, -1.5>, <-0.2, 2, 1.5> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow }
sphere { <-1.6, 0.6, 0>, 1 material { Glass } }
sphere { <-1.6, -1.3, 0>, 0.6 material { Glass } scale <1.3, 1, 1> }

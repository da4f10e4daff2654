// Conformance (kept with the stability tests): light_source { looks_like }.
// The object is moved to the light's position as of `looks_like`, the
// light's later transforms move both (the tilted pair), and it casts no
// shadow from any light, its own or another (the floor under the bulbs).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -8> look_at <0, 1, 0> angle 55 }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.75> } }
sphere { <0, 0.5, 0>, 0.5 pigment { color rgb <0.9, 0.3, 0.3> } }

#declare Bulb = sphere { 0, 0.3 pigment { color rgb <1, 0.85, 0.3> } finish { ambient 1 diffuse 0 } }
#declare Pair = union {
    object { Bulb }
    sphere { <0.7, 0, 0>, 0.18 pigment { color rgb <0.3, 0.8, 1> } finish { ambient 1 diffuse 0 } }
}

// An identifier with modifiers, then a transform after looks_like.
light_source { <-2.5, 1.2, 0> color rgb 0.7 looks_like { Bulb scale 0.8 } translate <0, 0.5, 0> }
// A transform before looks_like (the pair stays level) ...
light_source { <2, 1.4, -1> color rgb 0.5 rotate z * 20 looks_like { object { Pair } } }
// ... and after it (the pair tilts with the light).
light_source { <0.5, 2.6, 1.5> color rgb 0.4 looks_like { object { Pair } } rotate z * 25 }

// Stability: every polynomial shape (torus, poly, cubic, quartic, blob with
// sphere and cylinder components), with and without sturm, scaled as a
// whole by S. The images at S = 1e-4, 1 and 1e5 must agree
// (tests/stability/CMakeLists.txt). Half the shapes are written with S in
// their numbers where the syntax allows it (blob components), the rest are
// placed with `scale S`.
//
//     frameray polynomial_scale.pov +W320 +H240 Declare=S=1e5
#version 3.7;
#ifndef (S) #declare S = 1; #end
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
#include "shapesq.inc"

camera { location <0, 4, -9> * S look_at <0, 0.5, 0> * S angle 50 }
light_source { <-6, 11, -7> * S color rgb 1 }
#declare Matte = finish { ambient 0.15 diffuse 0.8 phong 0.3 }

// The floor is clipped 80 units (x S) around the camera: povray 3.7 sees
// nothing from 1e7 units on, and frameray follows it (conformance
// robust_far_camera), so an endless floor would end at a scale-dependent
// horizon. Clipped, every visible point stays within that distance.
plane { y, -0.5 * S clipped_by { sphere { <0, 0, -9> * S, 80 * S } }
        pigment { color rgb <0.75, 0.75, 0.7> } finish { Matte } }

torus { 1, 0.3 rotate x * -30 scale S translate <-3, 0.5, 0> * S pigment { color rgb <0.9, 0.4, 0.2> } finish { Matte } }
torus { 0.8, 0.08 sturm rotate z * 60 scale S translate <-1, 0.6, 1.5> * S pigment { color rgb <0.9, 0.8, 0.2> } finish { Matte } }
object { Piriform rotate z * 90 scale S translate <-0.6, 0.3, -1.5> * S pigment { color rgb <0.4, 0.85, 0.4> } finish { Matte } }
object { Torus_40_12 sturm scale 0.1 * S translate <1.2, 0.2, 1.2> * S pigment { color rgb <0.3, 0.6, 0.9> } finish { Matte } }
object { Twin_Glob clipped_by { box { -2, 2 } } scale 0.7 * S translate <3, 0.4, 0> * S pigment { color rgb <0.8, 0.4, 0.9> } finish { Matte } }
cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0, 0, 0, -1, 0>
    clipped_by { sphere { 0, 0.9 } } rotate x * -60 scale S translate <1.5, 0.5, -1.8> * S
    pigment { color rgb <0.9, 0.6, 0.5> } finish { Matte } }
blob {
    threshold 0.5
    sphere { <-0.4, 0, 0> * S, 0.9 * S, 1 }
    sphere { <0.4, 0.2, 0> * S, 0.9 * S, 1 }
    cylinder { <0, -0.4, -0.5> * S, <0, 0.8, -0.5> * S, 0.4 * S, 1 }
    translate <0.3, 0.3, 0> * S
    pigment { color rgb <0.95, 0.95, 0.95> } finish { Matte }
}
blob {
    threshold 0.6
    sphere { 0, 0.7, 1 scale <1.5, 1, 1> }
    cylinder { <0, 0, 0>, <0, 1, 0>, 0.4, 1 }
    sturm
    scale S translate <3, 0.4, 2> * S
    pigment { color rgb <0.5, 0.9, 0.9> } finish { Matte }
}

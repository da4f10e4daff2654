// Stability: every primitive frameray has, with shadows from a point
// light, scaled as a whole by S (camera, light and objects). The images at
// S = 1e-4, 1 and 1e5 must agree (tests/stability/CMakeLists.txt): nothing
// in the renderer may depend on the absolute size of a scene. Half of the
// shapes have S written into their coordinates (world-sized object space),
// the other half are placed with `scale S` (unit-sized object space).
//
//     frameray scale_all_primitives.pov +W320 +H240 Declare=S=1e-4
#version 3.7;
#ifndef (S) #declare S = 1; #end
global_settings { assumed_gamma 1.0 }

camera { location <0.5, 4, -9> * S look_at <0, 0.7, 0> * S angle 50 }
light_source { <-6, 11, -7> * S color rgb 1 }

#declare Matte = finish { ambient 0.15 diffuse 0.8 }

// The floor is clipped 80 units (x S) around the camera: povray 3.7 sees
// nothing from 1e7 units on, and frameray follows it (conformance
// robust_far_camera), so an endless floor would end at a scale-dependent
// horizon. Clipped, every visible point stays within that distance.
plane { y, 0 clipped_by { sphere { <0.5, 0, -9> * S, 80 * S } }
        pigment { color rgb <0.75, 0.75, 0.7> } finish { Matte } }

sphere { <-3, 0.8, 0.5> * S, 0.8 * S pigment { color rgb <0.9, 0.3, 0.25> } finish { Matte phong 0.4 } }

box { <-1.6, 0, -2.4> * S, <-0.6, 0.7, -1.4> * S pigment { color rgb <0.3, 0.6, 0.9> } finish { Matte } }

cylinder { <0, 0, 0>, <0, 1.3, 0>, 0.45 scale S translate <1.6, 0, -1.8> * S
    pigment { color rgb <0.95, 0.8, 0.3> } finish { Matte } }

cone { <3.2, 0, 0.3> * S, 0.65 * S, <3.2, 1.6, 0.3> * S, 0.05 * S
    pigment { color rgb <0.4, 0.85, 0.4> } finish { Matte } }

// A disc standing up, facing the camera half-way, with a hole.
disc { <0, 0, 0>, <0.5, 0, -1>, 0.6, 0.2 rotate z * 10 scale S translate <-3.3, 0.75, -2.2> * S
    pigment { color rgb <0.8, 0.4, 0.9> } finish { Matte } }

triangle { <-1.2, 0, 2> * S, <0.4, 0, 2.6> * S, <-0.4, 1.8, 2.3> * S
    pigment { color rgb <0.3, 0.8, 0.8> } finish { Matte } }

smooth_triangle {
    <0.8, 0, 2.4> * S, <-0.5, 0.3, -1>, <2.4, 0, 2.0> * S, <0.5, 0.3, -1>, <1.6, 1.6, 2.2> * S, <0, 1, -0.6>
    pigment { color rgb <0.9, 0.6, 0.4> } finish { Matte phong 0.3 } }

// An ellipsoid as a quadric: x^2 + 2 y^2 + z^2 = 0.3.
quadric { <1, 2, 1>, <0, 0, 0>, <0, 0, 0>, -0.3 scale S translate <0.2, 0.4, -0.6> * S
    pigment { color rgb <0.95, 0.95, 0.95> } finish { Matte phong 0.5 } }

// CSG: a box drilled by a cylinder minus a sphere bite, and a lens.
difference {
    box { <-0.6, 0, -0.6>, <0.6, 1.1, 0.6> }
    cylinder { <0, 0.55, -1>, <0, 0.55, 1>, 0.3 }
    sphere { <0.6, 1.1, -0.6>, 0.45 }
    rotate y * 25 scale S translate <-1.2, 0, 0.6> * S
    pigment { color rgb <0.85, 0.55, 0.2> } finish { Matte }
}
intersection {
    sphere { <0, 0, -0.45> * S, 0.7 * S }
    sphere { <0, 0, 0.45> * S, 0.7 * S }
    rotate y * 40 translate <1.9, 0.55, 0.4> * S
    pigment { color rgb <0.3, 0.4, 0.95> } finish { Matte phong 0.6 } }

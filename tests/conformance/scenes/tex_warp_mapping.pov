// Conformance: the mapping warps (cylindrical, spherical, toroidal, planar)
// with orientation, dist_exp and major_radius, in pigments and a normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { checker rgb <0.2, 0.2, 0.5>, rgb <0.9, 0.9, 0.7> scale <0.125, 1, 0.5> warp { cylindrical } } }
sphere { <-2.6, 1, 0>, 1 pigment { checker rgb <0.8, 0.2, 0.1>, rgb <0.9, 0.9, 0.9> scale <0.125, 0.125, 1> warp { spherical } translate <-2.6, 1, 0> } }
sphere { <0, 1, 0>, 1 pigment { gradient x color_map { [0 rgb <0, 0.3, 0>] [0.5 rgb <0.9, 1, 0.2>] [1 rgb <0, 0.3, 0>] } scale 0.25 warp { spherical orientation <1, 2, 3> dist_exp 1.5 } translate <0, 1, 0> } }
torus { 0.8, 0.35 rotate x * -50 translate <2.6, 1.1, 0>
  pigment { checker rgb <0.1, 0.4, 0.8>, rgb 1 scale <0.0625, 0.125, 1> warp { toroidal major_radius 0.8 } rotate x * -50 translate <2.6, 1.1, 0> } }
box { <-3.6, 0, 1.6>, <-1.6, 2.4, 2.4> pigment { brick rgb 0.6, rgb <0.7, 0.3, 0.2> scale 0.1 warp { planar x, 0.3 } } }
box { <-1, 0, 1.6>, <1, 2.4, 2.4> pigment { gradient x color_map { [0 rgb 0.1] [1 rgb <1, 0.7, 0.3>] } scale 0.3 warp { cylindrical orientation x dist_exp 1 } } }
box { <1.6, 0, 1.6>, <3.6, 2.4, 2.4> pigment { rgb 0.8 } normal { gradient y 0.6 scale 0.15 warp { toroidal orientation <0, 1, 1> dist_exp 0.5 major_radius 1.5 } translate <2.6, 1.2, 1.6> } }

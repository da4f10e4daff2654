// uv_mapping with normals (povray 3.7, measured): in a uv-mapped texture
// the pattern sits on the surface's uv while the object's transformations
// (and those after a uv-mapped texture identifier) still turn its
// perturbation, also in the entries of a uv-mapped texture map;
// uv_mapping in the normal itself is turned by neither.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6.5> look_at <0, 0.2, 0> angle 55 }
light_source { <-5, 8, -7> color rgb 1 }
light_source { <6, 2, -5> color rgb <0.35, 0.4, 0.5> }
plane { y, -1.2 pigment { rgb <0.7, 0.68, 0.62> } }

#declare TBumps = texture { uv_mapping pigment { rgb <0.9, 0.85, 0.75> }
  normal { bumps 0.8 scale <0.05, 0.1, 1> } finish { phong 0.5 } }
#declare NWrinkles = normal { uv_mapping wrinkles 1 scale 0.08 }

sphere { 0, 1 texture { TBumps } rotate <30, 20, 0> translate <-2.6, 0, 0.8> }
box { <-0.8, -0.8, -0.8>, <0.8, 0.8, 0.8>
  texture { uv_mapping pigment { checker rgb <0.8, 0.3, 0.2> rgb <0.9, 0.9, 0.8> scale 0.0625 }
    normal { dents 0.7 scale 0.02 } }
  rotate <-25, 35, 0> translate <-0.2, -0.1, 1.2> }
torus { 0.8, 0.35 texture { TBumps rotate y * 40 } rotate <-50, 20, 0> translate <2.3, 0, 1.2> }
sphere { 0, 0.9 pigment { rgb <0.5, 0.7, 0.9> } normal { NWrinkles scale 3 } finish { specular 0.6 }
  rotate <-40, 0, 20> translate <-1.4, -0.3, -1.6> }
lathe { cubic_spline 6, <0.1, -1.2>, <0.4, -1>, <0.8, -0.4>, <0.5, 0.3>, <0.35, 1>, <0.1, 1.2>
  pigment { rgb <0.95, 0.7, 0.3> } normal { uv_mapping gradient x 0.8 scale 0.1 }
  rotate z * 20 translate <1.2, -0.1, -1.5> }
// A uv-mapped texture map: its entries' normals turn with the object too.
box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5>
  texture { uv_mapping gradient x texture_map {
    [0 pigment { rgb <0.9, 0.3, 0.2> }]
    [1 pigment { rgb <0.3, 0.4, 0.9> } normal { bumps 1 scale 0.02 }] } scale 0.125 }
  rotate <30, 50, 0> translate <3.4, -0.6, -0.8> }

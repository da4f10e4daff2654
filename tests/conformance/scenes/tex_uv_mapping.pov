// uv_mapping (povray 3.7's uv per shape, measured): image maps and
// patterns on a sphere, a box (the cube cross), a torus, a lathe, a sor
// with caps, a bicubic patch, a mesh2 with uv_vectors and a cylinder
// (no uv of its own: the world x and y). uv_mapping in a pigment and in a
// texture, with the transformations of the block that says uv_mapping,
// while the objects' transformations and those after a uv-mapped texture
// identifier (the sor's `scale 0.5`) leave the uv pattern where it is.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -7.5> look_at <0, 0.3, 0> angle 58 }
light_source { <-5, 9, -8> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.35 }
plane { y, -1.2 pigment { rgb <0.7, 0.68, 0.62> } }

#declare Grid = pigment { uv_mapping image_map { png "image_grid.png" } }
#declare Checks = texture { uv_mapping
  pigment { checker rgb <0.9, 0.2, 0.1> rgb <0.95, 0.9, 0.7> scale <0.125, 0.25, 1> }
  finish { phong 0.4 } }

sphere { 0, 1 pigment { Grid } rotate y * 30 scale 1.1 translate <-3, 0.2, 1> }
box { <-0.8, -0.8, -0.8>, <0.8, 0.8, 0.8> pigment { Grid } rotate <-25, 35, 0> translate <-0.6, 0, 1.2> }
torus { 0.8, 0.35 texture { Checks } rotate x * -40 translate <1.8, 0, 1.4> }
lathe { cubic_spline 6, <0.1, -1.2>, <0.4, -1>, <0.8, -0.4>, <0.5, 0.3>, <0.35, 1>, <0.1, 1.2>
  texture { uv_mapping pigment { gradient x color_map { [0 rgb <0.1, 0.3, 0.9>] [1 rgb <0.9, 0.9, 0.2>] } }
    finish { specular 0.5 } scale <1, 0.2, 1> }
  scale 0.8 translate <3.6, -0.2, 0.3> }
sor { 5, <0.3, -1.5>, <0.5, -1>, <0.9, 0.2>, <0.5, 0.8>, <0.4, 1.2>
  texture { Checks scale 0.5 }
  rotate x * -35 scale 0.7 translate <-3.2, -0.5, -1.6> }
bicubic_patch { type 1 u_steps 3 v_steps 3
  <-1, -1, 0>, <-0.3, -1, 0.6>, <0.3, -1, -0.3>, <1, -1, 0>,
  <-1, -0.3, 0.4>, <-0.3, -0.3, 0.8>, <0.3, -0.3, 0.5>, <1, -0.3, 0.2>,
  <-1, 0.3, 0>, <-0.3, 0.3, 0.5>, <0.3, 0.3, 0.7>, <1, 0.3, 0.3>,
  <-1, 1, 0.2>, <-0.3, 1, 0.3>, <0.3, 1, 0>, <1, 1, 0.4>
  pigment { Grid } rotate <-30, 10, 0> scale 0.8 translate <-1.2, -0.2, -1.8> }
mesh2 {
  vertex_vectors { 4, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0> }
  uv_vectors { 4, <0, 0>, <2, 0>, <2, 1>, <0, 1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  pigment { Grid } rotate <-20, -15, 0> scale 0.75 translate <0.8, -0.2, -2> }
cylinder { -y, y, 0.6 texture { Checks } translate <2.7, -0.2, -1.8> }

// Conformance: density_file's `interpolate` is a pattern modifier that may
// come anywhere in the block, after a normal's bump size too (the example
// textures/patterns/densfile.pov): trilinear and nearest in a normal and a
// pigment. The right box starts at z = 0.1: at z = 0 its face would lie on
// a cell boundary, where povray rounds points to either side.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -4> look_at 0 angle 50 }
light_source { <-3, 4, -6> rgb 1 }
background { rgb 0.15 }
box { <-1.9, -0.9, 0>, <-0.1, 0.9, 1>
  pigment { rgb <1, 0.8, 0.5> }
  normal { density_file df3 "density_blob.df3", 1.5 interpolate 1 translate -0.5 scale 1.8 translate -x }
  finish { phong 0.6 }
}
box { <0.1, -0.9, 0.1>, <1.9, 0.9, 1>
  pigment { density_file df3 "density_blob.df3" translate -0.5 interpolate 0 scale 1.8 translate x
    color_map { [0 rgb 0] [1 rgb <0.4, 0.8, 1>] } }
  normal { density_file df3 "density_blob.df3", 0.8 interpolate 0 translate -0.5 scale 1.8 translate x }
}

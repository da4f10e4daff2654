// image_map map_type 2 (cylindrical), repeating and once, and map_type 5
// (torus) on a torus-like ring of spheres.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.2, 0> angle 50 }
light_source { <-4, 5, -6> color rgb 1 }
background { rgb <0.1, 0.2, 0.3> }
cylinder { <0, -1, 0>, <0, 1.5, 0>, 0.8
  pigment { image_map { png "image_grid.png" map_type 2 } scale <1, 0.8, 1> }
  rotate y*40 translate <-1.4, 0, 0>
}
cylinder { <0, -1, 0>, <0, 1.5, 0>, 0.8
  pigment { image_map { png "image_grid.png" map_type 2 once } }
  rotate y*-20 translate <1.4, 0, 0>
}
#for (I, 0, 11)
  sphere { <1, 0, 0>, 0.3
    pigment { image_map { png "image_grid.png" map_type 5 } rotate y*-I*30 }
    rotate y*I*30 scale 0.9 translate <0, -1.2, 0.5>
  }
#end

// Conformance: global_settings { noise_generator 1 } is the generator of
// every pattern that names none (bozo, granite, wrinkles in a normal,
// turbulence on a gradient) and of functions.inc's f_noise3d in an
// isosurface and a function pattern; a pattern's own noise_generator 2
// still wins (the right sphere). Generator 1 clips where 2 stretches, so
// the two differ over most of each surface.
#version 3.7;
global_settings { assumed_gamma 1.0 noise_generator 1 }
#include "functions.inc"
camera { location <0, 2.5, -9> look_at <0, 0.4, 0> angle 50 }
light_source { <-6, 12, -10> rgb 1 }
background { rgb <0.1, 0.12, 0.2> }

plane { y, -1
  pigment { bozo scale 0.6 color_map { [0 rgb <0.9, 0.8, 0.6>] [1 rgb <0.2, 0.3, 0.5>] } }
}
sphere { <-2.6, 0, 0>, 1
  pigment { granite scale 2 color_map { [0 rgb 1] [0.5 rgb <0.8, 0.2, 0.1>] [1 rgb 0] } }
  normal { wrinkles 0.8 scale 0.3 }
}
sphere { <0, 0, 0>, 1
  pigment { gradient y turbulence 0.8 scale 0.5
    color_map { [0 rgb <0.1, 0.6, 0.2>] [1 rgb <0.9, 0.9, 0.3>] } }
}
sphere { <2.6, 0, 0>, 1
  pigment { bozo noise_generator 2 scale 0.4
    color_map { [0 rgb <0.9, 0.8, 0.6>] [1 rgb <0.2, 0.3, 0.5>] } }
}
isosurface {
  function { y - 0.6 * f_noise3d(x * 2, 0, z * 2) }
  contained_by { box { <-3.5, -0.2, -1.5>, <3.5, 1, -1> } }
  max_gradient 2.2
  translate <0, 1.6, 3>
  pigment { function { f_noise3d(x * 3, y * 3, z * 3) }
    color_map { [0 rgb <0.2, 0.2, 0.8>] [1 rgb <1, 0.6, 0.2>] } }
}

// black_hole repeat and turbulence (textures/pigments/blkhole.pov): a hole
// in every cell of the repeat lattice, its centre kept at least a radius
// above the cell's lower faces, moved by the turbulence vector times
// povray's warp random numbers for the cell; and a strength above 1
// capped at 1 (the left half).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right x * 8 up y * 6 }
#declare Checks = pigment { checker rgb 1 rgb <0.1, 0.2, 0.6> scale 0.2 }
plane { z, 0
    pigment { Checks
        warp { black_hole <0, 0, 0>, 0.5 falloff 3 strength 0.75 inverse
               repeat <2, 1.5, 0> turbulence <1.0, 0.5, 0> }
        warp { black_hole <0.15, 0.125, 0>, 0.35 falloff 2 strength 1.0
               repeat <1.25, 1.25, 0> turbulence <0.25, 0.25, 0> } }
    finish { ambient 1 diffuse 0 }
    clipped_by { box { <0, -4, -1>, <5, 4, 1> } } }
plane { z, 0
    pigment { Checks
        warp { black_hole <1, 0.5, 0>, 0.6 falloff 1.5 strength 3 repeat <2.2, 1.6, 0> } }
    finish { ambient 1 diffuse 0 }
    clipped_by { box { <-5, -4, -1>, <0, 4, 1> } } }

// Patterns given without a colour_map take povray's default map for the
// pattern, also inside pigment_map entries and list-pattern pigments
// (issue 22, pigmap/txtrmap): radial runs cyan, yellow, magenta and back
// to cyan; the plain mandel (exponent 2) runs black, cyan, yellow, magenta
// and cyan within its first tenth; mandel exponent 3 and julia are grey.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right 8 * x up 6 * y }
#default { finish { ambient 1 diffuse 0 } }
plane { z, 0 pigment { radial rotate x * 90 translate <-2.7, 1.5, 0> } clipped_by { box { <-4, 0, -1>, <-1.4, 3, 1> } } }
plane { z, 0
    pigment { gradient x pigment_map { [0.2 rgb <0.1, 0.2, 0.3>] [0.5 radial frequency 3 rotate x * 90] [0.8 rgb 1] }
              scale 2.6 translate -1.3 * x }
    clipped_by { box { <-1.3, 0, -1>, <1.3, 3, 1> } } }
plane { z, 0
    pigment { checker pigment { radial frequency 5 rotate x * 90 translate <0.5, 0.5, 0> } pigment { rgb 0.5 } translate <0.2, 0.5, 0> }
    clipped_by { box { <1.4, 0, -1>, <4, 3, 1> } } }
plane { z, 0 pigment { mandel 200 scale 0.8 translate <-2.5, -1.5, 0> }
    clipped_by { box { <-4, -3, -1>, <-1.4, 0, 1> } } }
plane { z, 0 pigment { mandel 200 exponent 3 exponent 2 scale 0.8 translate <0.2, -1.5, 0> }
    clipped_by { box { <-1.3, -3, -1>, <1.3, 0, 1> } } }
plane { z, 0 pigment { mandel 40 exponent 3 scale 0.8 translate <2.7, -1.5, 0> }
    clipped_by { box { <1.4, -3, -1>, <4, 0, 1> } } }

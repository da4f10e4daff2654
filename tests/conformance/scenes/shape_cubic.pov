// Conformance: cubic { <20 coefficients> } in povray's term order (x³, x²y,
// x²z, x², xy², xyz, xy, xz², xz, x, y³, y²z, y², yz², yz, y, z³, z², z, 1):
// a cubic saddle z = x³ - y³ clipped by a sphere, and an asymmetric cubic
// whose mixed terms would show any ordering mistake, clipped by a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -6> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, -1.5 pigment { color rgb <0.75, 0.75, 0.7> } }

cubic {
    <1, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     -1, 0, 0, 0, 0, 0, 0, 0, -1, 0>
    clipped_by { sphere { 0, 1.2 } }
    rotate x * -60 translate <-1.4, 0.2, 0>
    pigment { color rgb <0.9, 0.5, 0.2> } finish { phong 0.4 }
}
cubic {
    <0, 0.7, 0, 1, 0, 2.5, 0, 0, 0, 0.2,
     0, 0, 1, -0.4, 0, 0, 0, 1, 0, -1>
    clipped_by { box { -1.3, 1.3 } }
    rotate y * 20 translate <1.5, 0.2, 0.5>
    pigment { color rgb <0.3, 0.6, 0.9> } finish { phong 0.4 }
}

// Conformance: a glass torus (refraction needs the torus's every crossing
// and its inside test) and a mirrored torus over a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -6> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, -1 pigment { checker color rgb <0.9, 0.9, 0.85> color rgb <0.3, 0.35, 0.5> } }

torus { 1, 0.4 rotate x * -70 translate <-1.4, 0.4, 0>
    pigment { color rgbf <0.95, 1, 0.95, 0.9> } finish { phong 0.6 }
    interior { ior 1.5 } }
torus { 0.8, 0.3 rotate z * 20 translate <1.6, 0, 0.8>
    pigment { color rgb 0.2 } finish { reflection 0.7 phong 0.5 } }
sphere { <1.6, 0.3, -1.2>, 0.35 pigment { color rgb <0.9, 0.3, 0.2> } }

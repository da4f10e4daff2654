// Conformance: blob cylinder components (capsule fields) joined to sphere
// components, a scaled cylinder component, and a threshold close to the
// components' strength (thin shapes).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -7> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }

blob {
    threshold 0.5
    cylinder { <-1, 0, 0>, <1, 0, 0>, 0.5, 1 }
    cylinder { <0, -0.8, 0>, <0, 0.9, 0>, 0.45, 1 }
    sphere { <1, 0, 0>, 0.8, 1 }
    rotate y * 30 translate <-1.6, 0.3, 0.4>
    pigment { color rgb <0.9, 0.5, 0.2> } finish { phong 0.5 }
}
blob {
    threshold 0.3
    cylinder { <0, 0, 0>, <0, 1.5, 0>, 0.5, 1 scale <1, 1, 2> rotate x * -20 }
    cylinder { <-0.8, 0, 0>, <0.8, 0, 0>, 0.4, 1.2 }
    translate <1.2, -0.3, 1>
    pigment { color rgb <0.3, 0.8, 0.35> } finish { phong 0.4 }
}
blob {
    threshold 0.9
    cylinder { <-0.7, 0, 0>, <0.7, 0, 0>, 0.7, 1 }
    sphere { <0, 0, 0>, 0.7, 1 }
    translate <1.7, 0, -1.6>
    pigment { color rgb <0.3, 0.5, 0.95> } finish { phong 0.3 }
}

// Conformance: blob with sphere components (povray's field
// strength * (1 - r²/R²)²): merging pairs, a negative component carving a
// dent, a transformed (ellipsoidal) component, the 2.0 `component` form,
// and a sturm blob.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -7> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }

blob {
    threshold 0.6
    sphere { <-0.5, 0, 0>, 1, 1 }
    sphere { <0.5, 0, 0>, 1, strength 1 }
    sphere { <0, 0.6, 0>, 0.9, 0.8 }
    translate <-1.9, 0.2, 0.5>
    pigment { color rgb <0.9, 0.5, 0.2> } finish { phong 0.5 }
}
blob {
    threshold 0.5
    sphere { 0, 1.2, 1.5 }
    sphere { <0, 0.9, -0.6>, 0.8, -1.5 }
    sphere { <0, 0, 0>, 0.6, 1 scale <2.5, 0.6, 0.6> rotate z * 30 translate <0, -0.3, 0> }
    translate <0.4, 0.1, 1.2>
    pigment { color rgb <0.3, 0.8, 0.35> } finish { phong 0.4 }
}
blob {
    threshold 0.4
    component 1, 0.8, <0, 0, 0>
    component 1, 0.8, <0.6, 0.3, 0>
    component 0.7, 0.6, <0.2, 0.8, 0.1>
    sturm
    translate <2.1, -0.2, -0.6>
    pigment { color rgb <0.3, 0.5, 0.95> } finish { phong 0.3 }
}

// Conformance: the matrix transformation with shear, on primitives and on
// a CSG object: a sheared box, cylinder, cone and torus-free union; shear
// combined with rotate and translate; normals must follow the inverse
// transpose.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 55 }

light_source { <-5, 9, -8> color rgb <1, 1, 1> }
light_source { <7, 4, -4> color rgb <0.35, 0.35, 0.35> }

plane { y, 0 pigment { color rgb <0.7, 0.7, 0.7> } }

// x shifts with height.
box { <-0.6, 0, -0.6>, <0.6, 1.5, 0.6>
    matrix < 1, 0, 0,
             0.6, 1, 0,
             0, 0, 1,
             -3, 0, 0 >
    pigment { color rgb <0.9, 0.4, 0.2> } finish { phong 0.4 } }

cylinder { <0, 0, 0>, <0, 1.8, 0>, 0.5
    matrix < 1, 0, 0,
             0, 1, 0.5,
             0, 0, 1,
             -1, 0, 0 >
    pigment { color rgb <0.3, 0.8, 0.4> } }

cone { <0, 0, 0>, 0.7, <0, 1.6, 0>, 0.1
    matrix < 1, 0, 0.3,
             -0.5, 1, 0,
             0, 0, 1,
             0, 0, 0 >
    rotate y * 30 translate <1, 0, 0>
    pigment { color rgb <0.3, 0.4, 0.95> } }

difference {
    box { <-0.7, 0, -0.7>, <0.7, 1.4, 0.7> }
    sphere { <0, 1.4, 0>, 0.7 }
    matrix < 1, 0, 0,
             0.4, 1, 0.4,
             0, 0, 1,
             3, 0, 0.5 >
    pigment { color rgb <0.9, 0.8, 0.3> }
}

sphere { 0, 0.6
    matrix < 1.4, 0, 0,
             0.7, 0.7, 0,
             0, 0, 0.8,
             -1.8, 0.6, -2.2 >
    pigment { color rgb <0.8, 0.4, 0.9> } finish { specular 0.5 } }

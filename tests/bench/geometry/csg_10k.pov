// Benchmark (geometry): 10 000 small CSG objects (a box minus a sphere,
// intersected with a cylinder, every fifth one a union with a cone) on a
// 100 x 100 grid, with shadows from a point light. Run through
// tests/bench/suites/geometry.txt.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 22, -38> look_at <0, 0, 8> angle 60 }
light_source { <-30, 60, -40> color rgb 1 }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.65> } }
#declare Part = intersection {
    difference {
        box { <-0.2, 0, -0.2>, <0.2, 0.4, 0.2> }
        sphere { <0.2, 0.4, -0.2>, 0.18 }
    }
    cylinder { <0, -0.1, 0>, <0, 0.5, 0>, 0.25 }
}
#for (I, 0, 9999)
    #declare X = mod(I, 100);
    #declare Z = div(I, 100);
    #if (mod(I, 5) = 0)
        union { object { Part } cone { <0, 0.4, 0>, 0.15, <0, 0.7, 0>, 0 }
            rotate y * (I * 37) translate <X * 0.5 - 25, 0, Z * 0.5 - 5>
            pigment { color rgb <0.9, 0.6, X / 100> } }
    #else
        object { Part rotate y * (I * 37) translate <X * 0.5 - 25, 0, Z * 0.5 - 5>
            pigment { color rgb <0.4, Z / 100, 0.8> } }
    #end
#end

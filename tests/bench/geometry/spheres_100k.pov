// Benchmark (geometry): 100 000 small spheres on a 500 x 200 grid over a
// floor, with a point light for shadows; the #for loop also costs parse
// time. Run through tests/bench/suites/geometry.txt.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 30, -45> look_at <0, 0, 10> angle 60 }
light_source { <-30, 80, -40> color rgb 1 }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.65> } }
#declare R = seed(7);
#for (I, 0, 99999)
    #declare X = mod(I, 500);
    #declare Z = div(I, 500);
    sphere { <X * 0.2 - 50 + 0.05 * rand(R), 0.08 + 0.3 * rand(R), Z * 0.25 - 5>, 0.08
        pigment { color rgb <rand(R), 0.5, 1 - X / 500> } }
#end

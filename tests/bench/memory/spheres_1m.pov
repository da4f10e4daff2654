// Benchmark (memory, issue 23): 1 000 000 small spheres on a 1000 x 1000
// grid over a floor, each with its own pigment; peak memory against
// povray's is the measure. Run through tests/bench/suites/memory.txt.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 60, -60> look_at <0, 0, 40> angle 60 }
light_source { <-30, 80, -40> color rgb 1 }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.65> } }
#declare R = seed(7);
#for (I, 0, 999999)
    #declare X = mod(I, 1000);
    #declare Z = div(I, 1000);
    sphere { <X * 0.1 - 50 + 0.02 * rand(R), 0.04 + 0.1 * rand(R), Z * 0.1>, 0.04
        pigment { color rgb <rand(R), 0.5, 1 - X / 1000> } }
#end

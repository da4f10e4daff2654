// Benchmark (memory, issue 23): an array of 16 777 216 elements, every
// 4096th written with a float (the array's storage is the measure, not the
// loop); peak memory against povray's (about 145 MB). Run through
// tests/bench/suites/memory.txt.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare N = 16777216;
#declare A = array[N];
#for (I, 0, N - 1, 4096)
    #declare A[I] = I;
#end
camera { location <0, 0, -3> look_at 0 }
light_source { <-3, 3, -3> color rgb 1 }
sphere { 0, 1 pigment { color rgb <A[4096] / 8192, 0.5, 0.5> } }

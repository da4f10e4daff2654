// Benchmark (a): a macro from an include file called 100 000 times.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "macro_lib.inc"
#declare Sum = 0;
#for (I, 1, 100000)
    Accumulate(Sum, I)
#end
#debug concat("sum ", str(Sum, 0, 1), "\n")

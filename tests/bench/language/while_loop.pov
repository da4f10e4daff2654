// Benchmark (b): a #while loop of 1 000 000 iterations of arithmetic.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare I = 0;
#declare Acc = 0;
#while (I < 1000000)
    #declare Acc = Acc + mod(I, 7) * 0.5 - sqrt(I) / 1000;
    #declare I = I + 1;
#end
#debug concat("acc ", str(Acc, 0, 3), "\n")

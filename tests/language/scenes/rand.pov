// Language test: seed() and rand() streams: the exact sequences, stream
// independence, repeatability, seeds that are not positive integers, and
// the macros of rand.inc.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "rand.out" write

#macro Draw(Label, Stream, N)
  #write (Out, Label, ":")
  #for (I, 1, N) #write (Out, " ", str(rand(Stream), 0, 9)) #end
  #write (Out, "\n")
#end

#declare R1 = seed(0);
#declare R2 = seed(12345);
Draw("seed 0", R1, 8)
Draw("seed 12345", R2, 8)
Draw("seed 0 continued", R1, 4)

// Streams are independent: interleaving does not change the sequences
#declare A = seed(42);
#declare B = seed(7);
#write (Out, "interleaved 42/7:")
#for (I, 1, 4)
  #write (Out, " ", str(rand(A), 0, 9), "/", str(rand(B), 0, 9))
#end
#write (Out, "\n")
#declare A2 = seed(42);
Draw("seed 42 alone", A2, 4)
#declare B2 = seed(7);
Draw("seed 7 alone", B2, 4)

// Same seed, same sequence; new seed() restarts
#declare S1 = seed(99);
#declare S2 = seed(99);
#write (Out, "same seed twice equal:")
#for (I, 1, 5) #write (Out, " ", (rand(S1) = rand(S2))) #end
#write (Out, "\n")

// Other seed values
#declare Big = seed(2147483647);
Draw("seed 2147483647", Big, 3)
#declare Neg = seed(-5);
Draw("seed -5", Neg, 3)
#declare Frac = seed(3.7);
Draw("seed 3.7", Frac, 3)
#declare Three = seed(3);
Draw("seed 3", Three, 3)
#declare One = seed(1);
Draw("seed 1", One, 3)

// Statistics of a long run
#declare St = seed(2024);
#declare Sum = 0;
#declare Lo = 1;
#declare Hi = 0;
#for (I, 1, 10000)
  #declare R = rand(St);
  #declare Sum = Sum + R;
  #declare Lo = min(Lo, R);
  #declare Hi = max(Hi, R);
#end
#write (Out, "10000 draws: mean ", str(Sum / 10000, 0, 9), " min ", str(Lo, 0, 9), " max ", str(Hi, 0, 9), "\n")
#write (Out, "next after 10000: ", str(rand(St), 0, 9), "\n")

// rand() in expressions and a stream held in an array
#declare E = seed(5);
#write (Out, "in expressions: ", str(int(rand(E) * 100), 0, 0), " ", vstr(3, <rand(E), rand(E), rand(E)>, ",", 0, 6), "\n")
#declare Streams = array[2] {seed(10), seed(20)}
#write (Out, "stream from array: ", str(rand(Streams[1]), 0, 9), " ", str(rand(Streams[0]), 0, 9), "\n")

// rand.inc
#include "rand.inc"
#declare RS = seed(314);
#write (Out, "rand.inc SRand ", str(SRand(RS), 0, 9), "\n")
#write (Out, "rand.inc RRand(10,20) ", str(RRand(10, 20, RS), 0, 9), "\n")
#write (Out, "rand.inc VRand ", vstr(3, VRand(RS), ",", 0, 9), "\n")
#write (Out, "rand.inc VRand_In_Box ", vstr(3, VRand_In_Box(<-1,-1,-1>, <1,1,1>, RS), ",", 0, 9), "\n")
#write (Out, "rand.inc Rand_Normal ", str(Rand_Normal(0, 1, RS), 0, 9), "\n")
#write (Out, "rand.inc VRand_On_Sphere ", vstr(3, VRand_On_Sphere(RS), ",", 0, 9), "\n")
#write (Out, "rand.inc Prob(0.5) ", Prob(0.5, RS), "\n")
#fclose Out

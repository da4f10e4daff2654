// Language test: #while and #for loops (steps, negative and fractional
// steps, empty ranges, the loop variable), #break in loops, switches and
// macros, and nesting.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "loops.out" write

// #while
#declare Count = 0;
#write (Out, "while:")
#while (Count < 5)
  #write (Out, " ", Count)
  #declare Count = Count + 1;
#end
#write (Out, " after ", Count, "\n")
#while (0)
  #write (Out, "never\n")
#end
#write (Out, "while false never entered\n")
#declare F = 1;
#while (F < 1000) #declare F = F * 3; #end
#write (Out, "while product ", F, "\n")
#declare Eps = 1;
#while (Eps) #declare Eps = Eps / 10; #end
#write (Out, "while stops below 1e-10: ", Eps, "\n")

// #for
#write (Out, "for 1..5:")
#for (I, 1, 5) #write (Out, " ", I) #end
#write (Out, " after ", I, "\n")
#write (Out, "for step 30:")
#for (I, 0, 330, 30) #write (Out, " ", I) #end
#write (Out, "\n")
#write (Out, "for negative step:")
#for (I, 5, 1, -2) #write (Out, " ", I) #end
#write (Out, " after ", I, "\n")
#write (Out, "for fractional step:")
#for (I, 0, 1, 0.25) #write (Out, " ", I) #end
#write (Out, "\n")
#write (Out, "for step 0.1 to 0.3:")
#for (I, 0, 0.3, 0.1) #write (Out, " ", I) #end
#write (Out, "\n")
#write (Out, "for step 0.1 to 1:")
#for (I, 0, 1, 0.1) #write (Out, " ", I) #end
#write (Out, "\n")
#write (Out, "for step overshoots 0..10 by 3:")
#for (I, 0, 10, 3) #write (Out, " ", I) #end
#write (Out, "\n")
#write (Out, "for empty range 1..0:")
#for (I, 1, 0) #write (Out, " never") #end
#write (Out, " after ", I, "\n")
#write (Out, "for single 2..2:")
#for (I, 2, 2) #write (Out, " ", I) #end
#write (Out, "\n")
#write (Out, "for expressions as bounds:")
#declare N = 3;
#for (I, N-2, N*2, N/3) #write (Out, " ", I) #end
#write (Out, "\n")
#write (Out, "for bounds evaluated once:")
#declare Limit = 3;
#for (I, 1, Limit) #write (Out, " ", I) #declare Limit = 10; #end
#write (Out, "\n")
#write (Out, "for body changes the variable:")
#for (J, 1, 10) #write (Out, " ", J) #declare J = J + 2; #end
#write (Out, "\n")
#write (Out, "for nested:")
#for (A, 1, 3)
  #for (B, A, 3)
    #write (Out, " ", A, B)
  #end
#end
#write (Out, "\n")

// #break
#write (Out, "break in while:")
#declare K = 0;
#while (1)
  #declare K = K + 1;
  #if (K > 3) #break #end
  #write (Out, " ", K)
#end
#write (Out, " after ", K, "\n")
#write (Out, "break in for:")
#for (I, 1, 100)
  #if (I * I > 20) #break #end
  #write (Out, " ", I)
#end
#write (Out, " after ", I, "\n")
#write (Out, "break leaves only the inner loop:")
#for (A, 1, 3)
  #for (B, 1, 3)
    #if (B > A) #break #end
    #write (Out, " ", A, B)
  #end
  #write (Out, " |")
#end
#write (Out, "\n")
#write (Out, "break in switch inside loop:")
#for (I, 1, 4)
  #switch (I)
    #case (2)
      #write (Out, " two")
    #break
    #else
      #write (Out, " ", I)
  #end
#end
#write (Out, "\n")
#macro EarlyExit(N)
  #write (Out, " enter", N)
  #if (N > 1) #break #end
  #write (Out, " body", N)
#end
#write (Out, "break ends macro:")
#for (I, 1, 3) EarlyExit(I) #end
#write (Out, "\n")

// Loops inside macros and macros inside loops
#macro Sum(From, To)
  #local S = 0;
  #for (Idx, From, To) #local S = S + Idx; #end
  S
#end
#write (Out, "loop in macro Sum(1,10) ", Sum(1, 10), " Sum(5,4) ", Sum(5, 4), "\n")
#declare Total = 0;
#for (I, 1, 4) #declare Total = Total + Sum(1, I); #end
#write (Out, "macro in loop ", Total, "\n")
#write (Out, "while with string condition:")
#declare S = "";
#while (strlen(S) < 4)
  #declare S = concat(S, "x");
  #write (Out, " ", S)
#end
#write (Out, "\n")
#fclose Out

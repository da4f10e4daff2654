// Language test: povray passes a lone identifier argument to a macro by
// reference, and #local on such a parameter assigns the caller's identifier
// as #declare does (the example scene language/tracevines.pov loops on it).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "macro_local_reference.out" write

#macro SetLocal(A) #local A = 5; #end
#declare X = 1;
SetLocal(X)
#write (Out, "local on a reference parameter ", X, "\n")

#macro Bump(A) #local Old = A; #local A = Old + 1; #end
#declare Y = 1;
Bump(Y) Bump(Y)
#write (Out, "counted twice ", Y, "\n")

// Through two macros: the inner parameter refers to the outer's caller.
#macro Outer(Q) SetLocal(Q) #end
#declare Z = 1;
Outer(Z)
#write (Out, "through two macros ", Z, "\n")

// A value argument is a copy: the caller keeps nothing.
#declare W = 1;
SetLocal(W + 0)
#write (Out, "an expression argument ", W, "\n")

// Inside the macro the parameter reads the new value.
#macro SetAndRead(A) #local A = A * 3; A #end
#declare V = 2;
#declare Read = SetAndRead(V);
#write (Out, "read back ", Read, " ", V, "\n")

// A loop driven by a by-reference counter (as tracevines' does).
#macro Step(I) #local I = I + 1; #end
#declare N = 0;
#declare Loops = 0;
#while (N < 4)
  Step(N)
  #declare Loops = Loops + 1;
#end
#write (Out, "loop ", N, " ", Loops, "\n")
#fclose Out

// Language test: #declare and #local scope rules in include files and
// macros (the reference's myscene.pov / myinc.inc / MyMacro example), macro
// parameters passed as identifiers or values, and #undef.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "scope.out" write

#declare A = 123;
#declare B = rgb <1,2,3>;
#declare C = 0;

#macro MyMacro(J, K, L)
  #write (Out, "macro: parameters ", J, " ", K, " ", L, "\n")
  #write (Out, "macro: sees the include's local A ", A, " and D ", D, "\n")
  #declare C = C + 1;
  #local B = 7;
  #write (Out, "macro: local B of another type ", B, "\n")
#end

// The reference also describes "#local D = D + 1;" inside MyMacro as
// creating a macro-local D from the include's D; POV-Ray 3.7 instead stops
// with "Cannot assign uninitialized identifier", so that is not tested.
#macro LocalIncrementD()
  #local D2 = D + 1;
  #write (Out, "macro: new macro-local D2 ", D2, "\n")
  #local D = 5;
  #write (Out, "macro: new macro-local D ", D, "\n")
#end

#macro DeclareIncrementD()
  #declare D = D + 1;
  #write (Out, "macro: #declare changed the include's D ", D, "\n")
#end

#declare IncludePass = 1;
#include "scope_inc.inc"
#write (Out, "main: after include A ", A, " C ", C, " B.red ", 0+B.red, "\n")
#write (Out, "main: D defined ", defined(D), " NewGlobal ", defined(NewGlobal), " NewLocal ", defined(NewLocal), " IncLocal ", defined(IncLocal), "\n")
#write (Out, "main: macro parameters gone ", defined(J), defined(K), defined(L), "\n")

#declare IncludePass = 2;
#include "scope_inc.inc"
#write (Out, "main: after second include C ", C, " IncCounter ", IncCounter, "\n")

// #local in the main file is the same as #declare
#local MainLocal = 5;
#macro ReadMainLocal() MainLocal #end
#write (Out, "main: #local in main file ", MainLocal, " seen from macro ", ReadMainLocal(), "\n")

// #declare of a name that is local to the macro changes the local one
#macro LocalThenDeclare()
  #local T = 1;
  #declare T = 2;
  #write (Out, "macro: local T after #declare ", T, "\n")
#end
LocalThenDeclare()
#write (Out, "main: T defined after macro ", defined(T), "\n")

// #declare of a new name inside a macro creates a global
#macro MakeGlobal() #declare MadeInMacro = 99; #local Temp = 1; #end
MakeGlobal()
#write (Out, "main: declared in macro ", MadeInMacro, " local gone ", defined(Temp), "\n")

// Parameters: a lone identifier can be changed by the macro, values cannot
#macro Increment(V)
  #declare V = V + 1;
#end
#declare Value = 5.0;
Increment(Value)
#write (Out, "param: Increment(Value) ", Value, "\n")
Increment(Value+0.0)
#write (Out, "param: Increment(Value+0.0) ", Value, "\n")
Increment(Value*1.0)
#write (Out, "param: Increment(Value*1.0) ", Value, "\n")
Increment((Value))
#write (Out, "param: Increment((Value)) ", Value, "\n")
#declare Vec = <1,2,3>;
Increment(Vec)
#write (Out, "param: Increment(Vec) ", Vec, "\n")

// A parameter hides a global of the same name
#declare P = 1000;
#macro ShowP(P) #write (Out, "param: hides global P ", P, "\n") #end
ShowP(7)
#write (Out, "main: global P unchanged ", P, "\n")

// #local in a macro hides a global only inside the macro
#declare G = 1;
#macro HideG() #local G = 2; #write (Out, "macro: local G ", G, "\n") #end
HideG()
#write (Out, "main: global G ", G, "\n")

// #undef removes the most local version first
#declare U = 1;
#macro UndefInside()
  #local U = 2;
  #write (Out, "macro: local U ", U, "\n")
  #undef U
  #write (Out, "macro: after #undef sees global U ", U, "\n")
  #undef U
  #write (Out, "macro: after second #undef U defined ", defined(U), "\n")
#end
UndefInside()
#write (Out, "main: U defined after macro ", defined(U), "\n")
#declare U = 3;
#write (Out, "main: U declared again ", U, "\n")
#undef MyMacro
#ifdef (MyMacro)
  #write (Out, "main: macro MyMacro still defined\n")
#else
  #write (Out, "main: macro MyMacro undefined by #undef\n")
#end
#ifdef (Increment)
  #write (Out, "main: macro Increment defined\n")
#end
#fclose Out

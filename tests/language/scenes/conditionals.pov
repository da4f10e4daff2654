// Language test: #if/#elseif/#else, #ifdef/#ifndef (with #else and
// #elseif), nesting, and #switch with #case, #range, #break, #else and
// fall-through between clauses.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "conditionals.out" write

// #if / #elseif / #else
#macro Classify(N)
  #if (N < 0)
    #write (Out, "if ", N, " negative\n")
  #elseif (N = 0)
    #write (Out, "if ", N, " zero\n")
  #elseif (N < 10)
    #write (Out, "if ", N, " small\n")
  #elseif (N < 10)
    #write (Out, "if ", N, " never reached\n")
  #else
    #write (Out, "if ", N, " large\n")
  #end
#end
Classify(-3)
Classify(0)
Classify(1e-11)
Classify(5)
Classify(50)
#if (1) #write (Out, "if without else true\n") #end
#if (0) #write (Out, "if without else never\n") #end
#if (0) #write (Out, "never\n") #elseif (0) #write (Out, "never\n") #end
#write (Out, "if with all false branches and no else\n")
#if (0) #else #write (Out, "if empty true branch, else taken\n") #end
#if (1) #else #write (Out, "never\n") #end

// Nesting, and skipped branches with directives in them
#declare Outer = 1;
#declare Inner = 0;
#if (Outer)
  #if (Inner)
    #write (Out, "nested never\n")
  #else
    #write (Out, "nested outer true inner false\n")
  #end
#else
  #if (1) #write (Out, "nested never (skipped branch)\n") #end
  #while (1) #end
  #declare Outer = 100;
#end
#write (Out, "nested skipped branch did not run: Outer ", Outer, "\n")
#if (0)
  #switch (1) #case (1) #write (Out, "never\n") #break #end
  #macro NotDefined() #end
  #error "skipped #error must not fire"
#end
#ifdef (NotDefined) #write (Out, "never\n") #else #write (Out, "macro in skipped branch not defined\n") #end
#if (0)
  This text is not parsed at all { [ < }
  #declare Junk = ;
#end
#write (Out, "garbage in skipped branch ignored\n")

// #ifdef / #ifndef
#declare Known = 1;
#ifdef (Known) #write (Out, "ifdef Known true\n") #else #write (Out, "ifdef Known false\n") #end
#ifdef (Unknown) #write (Out, "ifdef Unknown true\n") #else #write (Out, "ifdef Unknown false\n") #end
#ifndef (Known) #write (Out, "ifndef Known true\n") #else #write (Out, "ifndef Known false\n") #end
#ifndef (Unknown) #write (Out, "ifndef Unknown true\n") #else #write (Out, "ifndef Unknown false\n") #end
#ifdef (Unknown) #write (Out, "never\n") #elseif (Known = 1) #write (Out, "ifdef with elseif taken\n") #else #write (Out, "never\n") #end
#ifndef (Known) #write (Out, "never\n") #elseif (0) #write (Out, "never\n") #else #write (Out, "ifndef with elseif, else taken\n") #end
#declare Str = "text";
#declare Vec = <1,2,3>;
#ifdef (Str) #write (Out, "ifdef of a string identifier\n") #end
#ifdef (Vec) #write (Out, "ifdef of a vector identifier\n") #end
#ifdef (Classify) #write (Out, "ifdef of a macro\n") #end
#undef Known
#ifndef (Known) #write (Out, "ifndef after #undef\n") #end
#ifndef (Counter) #declare Counter = 0; #end
#ifndef (Counter) #declare Counter = 100; #end
#write (Out, "ifndef default value ", Counter, "\n")

// #switch
#macro Switch(Value)
  #write (Out, "switch ", Value, ":")
  #switch (Value)
    #case (1)
      #write (Out, " case1")
    #break
    #case (2)
      #write (Out, " case2")
    #break
    #range (3, 5)
      #write (Out, " range3-5")
    #break
    #range (4, 10)
      #write (Out, " range4-10")
    #break
    #else
      #write (Out, " else")
  #end
  #write (Out, "\n")
#end
Switch(1)
Switch(2)
Switch(3)
Switch(4)
Switch(5)
Switch(5.5)
Switch(10)
Switch(11)
Switch(-1)
Switch(1+1e-11)
Switch(2-1e-11)
Switch(3-1e-11)

// Without #break: the next clause's condition is still evaluated
#macro FallThrough(Value)
  #write (Out, "fallthrough ", Value, ":")
  #switch (Value)
    #case (1)
      #write (Out, " case1")
    #case (2)
      #write (Out, " case2")
    #range (1, 3)
      #write (Out, " range1-3")
    #case (4)
      #write (Out, " case4")
    #else
      #write (Out, " else")
  #end
  #write (Out, "\n")
#end
FallThrough(1)
FallThrough(2)
FallThrough(3)
FallThrough(4)
FallThrough(7)

// Several #case clauses sharing one body, #else only
#macro Shared(Value)
  #write (Out, "shared ", Value, ":")
  #switch (Value)
    #case (1)
    #case (2)
    #case (3)
      #write (Out, " one-to-three")
    #break
    #case (4)
      #write (Out, " four")
  #end
  #write (Out, "\n")
#end
Shared(1)
Shared(2)
Shared(3)
Shared(4)
Shared(5)
// (A #switch whose first clause is #else is a parse error in POV-Ray 3.7.)
#switch (7)
  #case (8)
    #write (Out, "never\n")
  #else
    #write (Out, "switch with one false case and else\n")
#end
#switch (7)
  #case (7)
    #write (Out, "switch break inside if:")
    #if (1)
      #write (Out, " before break")
      #break
    #end
    #write (Out, " never")
  #case (7)
    #write (Out, " never")
#end
#write (Out, "\n")
#switch (3)
  #case (3)
    #switch (1)
      #case (1) #write (Out, "nested switch inner") #break
      #else #write (Out, " never")
    #end
    #write (Out, " then outer\n")
  #break
  #else
    #write (Out, "never\n")
#end
#fclose Out

// Language test: macros used as functions (returning floats, vectors,
// colours and strings), token substitution, recursion, mutual recursion,
// returning values through identifier parameters, redefinition and macros
// calling macros.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "macros.out" write

// Return values
#macro Square(X) (X*X) #end
#macro Hypot(A, B) sqrt(Square(A) + Square(B)) #end
#macro Midpoint(P1, P2) ((P1 + P2) / 2) #end
#macro Greeting(Name) concat("Hello, ", Name, "!") #end
#macro Answer() 42 #end
#write (Out, "return float ", Square(7), " ", Square(1.5), " ", Square(-3)+1, "\n")
#write (Out, "return nested ", Hypot(3, 4), "\n")
#write (Out, "return vector ", Midpoint(<0,0,0>, <2,4,6>), "\n")
#write (Out, "return string ", Greeting("World"), "\n")
#write (Out, "no parameters ", Answer(), " ", Answer()*2, "\n")
#declare FromMacro = Square(5) + Answer();
#write (Out, "in a declaration ", FromMacro, "\n")
#write (Out, "in a vector literal ", <Square(2), Answer(), Square(Answer())>, "\n")

// The reference's Interpolate macro works for floats, vectors and colours
#macro Interpolate(T, T1, T2, P1, P2)
  (P1 + (T1 + T/(T2-T1)) * (P2-P1))
#end
#write (Out, "interpolate float ", Interpolate(5, 0, 15, 3.0, 5.5), "\n")
#write (Out, "interpolate vector ", Interpolate(5, 0, 15, <2,3,4>, <9,8,7>), "\n")
#declare Col = Interpolate(5, 0, 15, rgb <1,1,0>, rgb <0,1,1>);
#write (Out, "interpolate colour ", vstr(5, Col, ",", 0, 4), "\n")
#write (Out, "interpolate times 15 ", Interpolate(5, 0, 15, 3.0, 5.5)*15, "\n")
// Without the outer parentheses the body is substituted as tokens
#macro InterpolateBare(T, T1, T2, P1, P2)
  P1 + (T1 + T/(T2-T1)) * (P2-P1)
#end
#write (Out, "interpolate without parentheses times 15 ", InterpolateBare(5, 0, 15, 3.0, 5.5)*15, "\n")
#macro Plus() + #end
#write (Out, "token substitution 1 Plus() 2 ", 1 Plus() 2, "\n")
#macro OpenVector() <1, 2, #end
#write (Out, "token substitution partial vector ", OpenVector() 3>, "\n")

// Recursion
#macro Factorial(N)
  #if (N <= 1)
    1
  #else
    (N * Factorial(N - 1))
  #end
#end
#write (Out, "recursion factorial 0..10:")
#for (I, 0, 10) #write (Out, " ", Factorial(I)) #end
#write (Out, "\n")
#macro Fib(N)
  #if (N < 2)
    #local R = N;
  #else
    #local R = Fib(N - 1) + Fib(N - 2);
  #end
  R
#end
#write (Out, "recursion fibonacci 15 ", Fib(15), "\n")
#macro IsEven(N) #if (N = 0) 1 #else IsOdd(N - 1) #end #end
#macro IsOdd(N) #if (N = 0) 0 #else IsEven(N - 1) #end #end
#write (Out, "mutual recursion IsEven(10) ", IsEven(10), " IsOdd(7) ", IsOdd(7), " IsEven(7) ", IsEven(7), "\n")
#macro CountDown(N)
  #local Mine = N;
  #if (N > 0) CountDown(N - 1) #end
  #write (Out, " ", Mine)
#end
#write (Out, "recursion keeps each level's locals:")
CountDown(4)
#write (Out, "\n")
#macro Binary(N)
  #if (N < 2)
    str(N, 0, 0)
  #else
    concat(Binary(div(N, 2)), str(mod(N, 2), 0, 0))
  #end
#end
#write (Out, "recursion on strings Binary(37) ", Binary(37), "\n")
#macro Ackermann(M, N)
  #if (M = 0)
    #local Result = N + 1;
  #elseif (N = 0)
    #local Result = Ackermann(M - 1, 1);
  #else
    #local Result = Ackermann(M - 1, Ackermann(M, N - 1));
  #end
  Result
#end
#write (Out, "recursion Ackermann(2,3) ", Ackermann(2, 3), "\n")

// Returning values through parameters
#macro DivMod(A, B, Quotient, Remainder)
  #declare Quotient = div(A, B);
  #declare Remainder = mod(A, B);
#end
#declare Q = 0;
#declare R = 0;
DivMod(17, 5, Q, R)
#write (Out, "out parameters 17/5 ", Q, " remainder ", R, "\n")
#macro Swap(A, B)
  #local Tmp = A;
  #declare A = B;
  #declare B = Tmp;
#end
#declare First = "one";
#declare Second = "two";
Swap(First, Second)
#write (Out, "swap strings ", First, " ", Second, "\n")
#declare V1 = <1,2,3>;
#declare V2 = 9;
Swap(V1, V2)
#write (Out, "swap vector and float ", V1, " ", V2, "\n")
#macro Accumulate(Total, Amount) #declare Total = Total + Amount; #end
#declare Sum = 0;
#for (I, 1, 5) Accumulate(Sum, I) #end
#write (Out, "accumulate in loop ", Sum, "\n")

// Redefinition, macros calling macros, parameters of any type
#macro Version() 1 #end
#write (Out, "redefinition before ", Version(), "\n")
#macro Version() 2 #end
#write (Out, "redefinition after ", Version(), "\n")
#macro Twice(S) concat(S, S) #end
#macro Shout(S) strupr(Twice(S)) #end
#write (Out, "macro calling macros ", Shout("ab"), "\n")
#macro Describe(Label, F, V, S)
  #write (Out, "parameters of several types ", Label, " ", F, " ", V, " ", S, "\n")
#end
Describe("mixed", 1.5, <1,2>, "str")
Describe("expressions", 2*3, <1,2,3>*2, concat("a", "b"))
#macro Outer(N)
  #macro InnerDefined() 7 #end
  (N + InnerDefined())
#end
#write (Out, "macro defined inside a macro ", Outer(1), "\n")
#write (Out, "macro argument is another macro call ", Square(Square(2)), "\n")
#macro Args3(A, B, C) (A*100 + B*10 + C) #end
#write (Out, "argument order ", Args3(1, 2, 3), " ", Args3(3, 2, 1), "\n")
#write (Out, "arguments with parentheses and commas ", Args3((1), max(2, 0), <3,4>.x), "\n")
#fclose Out

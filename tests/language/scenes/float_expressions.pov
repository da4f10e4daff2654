// Language test: float literals, arithmetic precedence, unary operators,
// relational operators with POV-Ray's epsilon (1e-10) rules, logical
// operators, the conditional operator and how #write prints floats (%g).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "float_expressions.out" write

// Literals
#write (Out, "literals ", -2.0, " ", -4, " ", 34, " ", 3.4e6, " ", 2e-5, " ", .3, " ", 0.6, "\n")
#write (Out, "literals exp ", 1E3, " ", 1.5e+2, " ", 25e-1, " ", 1., " ", 007, "\n")

// Arithmetic precedence and associativity
#write (Out, "precedence 1+2*3 ", 1+2*3, "\n")
#write (Out, "precedence (1+2)*3 ", (1+2)*3, "\n")
#write (Out, "precedence 2*3-4/2 ", 2*3-4/2, "\n")
#write (Out, "left assoc 10-4-3 ", 10-4-3, "\n")
#write (Out, "left assoc 8/4/2 ", 8/4/2, "\n")
#write (Out, "left assoc 2*6/4*3 ", 2*6/4*3, "\n")
#write (Out, "division 7/2 ", 7/2, "\n")
#write (Out, "unary -2*-3 ", -2*-3, "\n")
#write (Out, "unary - -2 ", - -2, "\n")
#write (Out, "unary +3 ", +3, " ", 5 - +3, "\n")
#write (Out, "unary -(2+3)*2 ", -(2+3)*2, "\n")
#write (Out, "unary -2-3 ", -2-3, "\n")
#write (Out, "not !0 ", !0, " !5 ", !5, " !!2 ", !!2, " !-1 ", !-1, "\n")
#write (Out, "not binds tighter 1+!0 ", 1+!0, " !0*5 ", !0*5, "\n")
#write (Out, "nested parens ", ((((2)))+(3*(4-(1)))), "\n")

#declare Rows = 5.3;
#declare Cols = 6.15;
#declare Number = Rows*Cols;
#declare Count = 0;
#declare Count = Count+1;
#declare Count = Count+1;
#write (Out, "identifiers ", Number, " ", Count, " ", str(Number,0,6), "\n")

// How #write prints floats
#write (Out, "print large ", 1e20, " ", 123456, " ", 1234567, " ", -9876543.21, "\n")
#write (Out, "print small ", 0.0001, " ", 0.00001, " ", 1/3, " ", -2/3, " ", 1e-300*1e-300, "\n")
#write (Out, "print negative zero ", -0, " ", 0*-1, "\n")
#write (Out, "print 1/7 ", 1/7, " ", str(1/7,0,10), "\n")

// Relational operators (they need parentheses)
#write (Out, "lt ", (1 < 2), " ", (2 < 1), " ", (2 < 2), "\n")
#write (Out, "le ", (1 <= 2), " ", (2 <= 1), " ", (2 <= 2), "\n")
#write (Out, "gt ", (1 > 2), " ", (2 > 1), " ", (2 > 2), "\n")
#write (Out, "ge ", (1 >= 2), " ", (2 >= 1), " ", (2 >= 2), "\n")
#write (Out, "eq ", (1 = 2), " ", (2 = 2), " ", (0.1+0.2 = 0.3), "\n")
#write (Out, "ne ", (1 != 2), " ", (2 != 2), " ", (0.1+0.2 != 0.3), "\n")
#write (Out, "rel lower than arithmetic ", (2+3 = 5), " ", (2*3 > 5), " ", (1-1 < 0), "\n")
#write (Out, "rel chain (1<2<3) ", (1 < 2 < 3), " (3>2>1) ", (3 > 2 > 1), "\n")

// The epsilon rules: equality tolerates differences up to 1e-10
#write (Out, "eps eq ", (1 = 1+1e-11), " ", (1 = 1+1e-9), " ", (0 = 1e-10), " ", (0 = 1.01e-10), " ", (0 = -1e-10), "\n")
#write (Out, "eps ne ", (1 != 1+1e-11), " ", (1 != 1+1e-9), " ", (0 != 1e-10), " ", (0 != 1.01e-10), "\n")
#write (Out, "eps le ", (1 <= 1-1e-12), " ", (1 <= 1-1e-9), " ", (0 <= -1e-10), " ", (0 <= -2e-10), "\n")
#write (Out, "eps ge ", (1 >= 1+1e-12), " ", (1 >= 1+1e-9), " ", (0 >= 1e-10), " ", (0 >= 2e-10), "\n")
#write (Out, "eps lt ", (1 < 1+1e-12), " ", (0 < 1e-300), " ", (1+1e-12 < 1), "\n")
#write (Out, "eps gt ", (1+1e-12 > 1), " ", (1e-300 > 0), " ", (1 > 1+1e-12), "\n")

// Logical operators: operands are true when abs(value) > 1e-10
#write (Out, "and ", (1 & 1), " ", (1 & 0), " ", (0 & 0), " ", (0.5 & -2), "\n")
#write (Out, "or ", (1 | 1), " ", (1 | 0), " ", (0 | 0), " ", (0 | -3), "\n")
#write (Out, "logic same precedence (1|0&0) ", (1 | 0 & 0), " (0&0|1) ", (0 & 0 | 1), "\n")
#write (Out, "logic with rel ", (1 < 2 & 3 < 2), " ", (1 < 2 | 3 < 2), " ", (2 > 1 & 5 = 5), "\n")
#write (Out, "eps and ", (1e-11 & 1), " ", (1e-10 & 1), " ", (1.01e-10 & 1), " ", (-1e-9 & 1), "\n")
#write (Out, "eps or ", (1e-11 | 0), " ", (1e-9 | 0), "\n")
#write (Out, "eps not ", !1e-11, " ", !1e-10, " ", !1.01e-10, " ", !-1e-10, "\n")

// Conditional operator
#write (Out, "cond ", (1 ? 2 : 3), " ", (0 ? 2 : 3), " ", (-1 ? 2 : 3), "\n")
#write (Out, "cond nested ", (0 ? 1 : 1 ? 5 : 6), " ", (1 ? 0 ? 7 : 8 : 9), "\n")
#write (Out, "cond with rel ", (2 < 1 ? 10 : 20), " ", (2 > 1 & 1 ? 10 : 20), "\n")
#write (Out, "cond eps ", (1e-11 ? 2 : 3), " ", (1e-10 ? 2 : 3), " ", (1.01e-10 ? 2 : 3), "\n")
#write (Out, "cond arithmetic ", (1 ? 2 : 3)*10+1, "\n")
#declare Foo = 1; #declare Bar = 2; #declare This = 3; #declare That = 4;
#write (Out, "cond doc example ", ((This < That) & (Foo >= Bar) ? 100 : 200), "\n")

// Conditions of #if and #while use the same truth rule
#if (1e-11) #write (Out, "if 1e-11 true\n") #else #write (Out, "if 1e-11 false\n") #end
#if (1e-10) #write (Out, "if 1e-10 true\n") #else #write (Out, "if 1e-10 false\n") #end
#if (1.01e-10) #write (Out, "if 1.01e-10 true\n") #else #write (Out, "if 1.01e-10 false\n") #end
#if (-0.5) #write (Out, "if -0.5 true\n") #else #write (Out, "if -0.5 false\n") #end
#fclose Out

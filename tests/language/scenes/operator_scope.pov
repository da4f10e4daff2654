// Language test: where povray parses comparisons, '&', '|' and '? :'.
// They are read only inside parentheses (a single-argument function's
// parentheses count); at the top of an expression, in vector components and
// in multi-argument calls a '<' starts the next vector, which is why
// `box { <..> <..> }` needs no comma between its corners.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "operator_scope.out" write

#declare A = (1 < 2);
#declare B = 1 + (2 > 1);
#declare C = abs(1 < 2);
#declare D = -(3 = 3);
#declare E = sqrt(4 >= 4);
#declare F = (1 ? 4 : 5) + (0 ? 4 : 5);
#declare G = <(2 > 1), (1 & 0), (0 | 1)>;
#declare H = ("a" < "b");
#write (Out, A, " ", B, " ", C, " ", D, " ", E, " ", F, " ", G, " ", H, "\n")

// Corners without a comma, also when the first ends in a negative number.
#declare Box1 = box { <-4, -0.5, -1> <4, 0.5, 1> }
#write (Out, min_extent(Box1), max_extent(Box1), "\n")
#declare Cyl = cylinder { <0, -1, 0> <0, 2, 0> 0.5 }
#write (Out, min_extent(Cyl), max_extent(Cyl), "\n")
#declare Cone = cone { <0, 0, 0> 1 <0, 3, 0> 0.5 }
#write (Out, min_extent(Cone), max_extent(Cone), "\n")

// Conditions of directives are parenthesised expressions.
#if (2 > 1 & 3 > 2) #write (Out, "if: both\n") #end
#declare I = 0;
#while (I < 3 | I = 3) #declare I = I + 1; #end
#write (Out, "while: ", I, "\n")
#fclose Out

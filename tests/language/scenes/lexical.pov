// Language test: comments (nested block comments, // inside /* */),
// identifier spelling and case, white space, and directives placed between
// the tokens of other statements.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "lexical.out" write

// Comments
#declare A = 1; // a line comment ends the line #declare A = 2;
#write (Out, "line comment ", A, "\n")
/* a block comment
   #declare A = 3;
   spanning lines */
#write (Out, "block comment ", A, "\n")
/* This is a comment // This too /* This also */ */
#write (Out, "nested block comment ", A, "\n")
/* /* /* three levels */ #declare A = 4; */ #declare A = 5; */
#write (Out, "three levels of nesting ", A, "\n")
#declare B = 1 /* inside an expression */ + /* again */ 2;
#write (Out, "comments between tokens ", B, "\n")
// a line comment containing /* does not open a block comment
#write (Out, "line comment with /* ", B, "\n")
#write (Out, "comment markers inside strings [/* // */]\n")
#declare C = 10//comment right after a number
;
#write (Out, "comment after a number ", C, "\n")

// Identifiers
#declare Foo = 1;
#declare foo_ = 2;
#declare FOO = 3;
#declare F00 = 4;
#declare Foo_Bar_123 = 5;
#write (Out, "identifiers are case sensitive ", Foo, foo_, FOO, F00, Foo_Bar_123, "\n")
#declare ThisIdentifierIsExactlyFortyCharacters_x = 40;
#write (Out, "forty-character identifier ", ThisIdentifierIsExactlyFortyCharacters_x, "\n")
#declare Red_ = 1; #declare red_amount = 2;
#write (Out, "names starting like keywords ", Red_ + red_amount, "\n")

// White space
#declare      Spaced     =    (  1
    +
  2  )   *   3    ;
#write (Out, "free format ", Spaced, "\n")
#declare Tight=<1,2,3>+<3,2,1>;#write(Out,"no spaces ",Tight,"\n")
	#write	(Out,	"tabs\n")

// Directives between the tokens of other statements (POV-Ray 3.7 does not
// accept a directive right before the ';' of a float declaration, so the
// expressions below are parenthesised or vectors)
#declare D = (1 + #if (1) 2 #else 3 #end);
#write (Out, "#if inside an expression ", D, "\n")
#declare E = <1, #if (0) 5 #else 6 #end, 7>;
#write (Out, "#if inside a vector literal ", E, "\n")
#declare V = <1, 2 #if (1) , 3 #end >;
#write (Out, "#if adding a vector component ", V, "\n")
#declare F = (0
  #for (I, 1, 4)
    + I
  #end
);
#write (Out, "#for building an expression ", F, "\n")
#declare G = <
  #declare H = 2;
  H, H*2, H*3
>;
#write (Out, "#declare inside a vector literal ", G, " ", H, "\n")
#declare Sum = 0;
#declare T = <0 #while (Sum < 10) + 3 #declare Sum = Sum + 3; #end, 0, 0>;
#write (Out, "#while inside a vector literal ", T, "\n")
#declare S = sphere { <0, #if (1) 1 #else 2 #end, 0>, 1 }
#write (Out, "#if inside an object statement\n")
#write (Out, "#if inside #write ", 1 + #if (1) 2 #else 3 #end, "\n")
#write (Out, "#for inside #write ", 0 #for (I, 1, 4) + I #end, "\n")
#write (Out, "#switch inside #write ",
  #switch (2)
    #case (1) "one"
    #break
    #case (2) "two"
    #break
  #end
  , "\n")
#fclose Out

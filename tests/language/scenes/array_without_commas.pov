// Language test: the commas between an array initializer's elements are
// optional in povray 3.7 (the example textures/patterns/tiling.pov omits
// one between two colours, advanced/grenadine/lemon.inc one per row).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "array_without_commas.out" write
#declare A = array[4] { 1, 2 3, 4 };
#write (Out, "floats ", A[0], " ", A[1], " ", A[2], " ", A[3], "\n")
#declare B = array[2][2] { {1 2} {3, 4} };
#write (Out, "nested ", B[0][1], " ", B[1][0], "\n")
#declare V = array[3] { <1,2>, <3,4>
  <5,6> };
#write (Out, "vectors ", V[2].x, " ", V[2].y, "\n")
#declare C = array[3] { rgb <1,0,0> rgb <0,1,0>, rgb <0,0,1> };
#write (Out, "colours ", 0+C[1].green, " ", 0+C[2].blue, "\n")
#declare S = array[2] { "a" "b", };
#write (Out, "strings ", S[0], S[1], "\n")
#fclose Out

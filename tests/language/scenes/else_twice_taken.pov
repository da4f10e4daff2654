// A second #else after a taken #if branch: povray 3.7 skips both without
// an error (frameray warns); the value is the #if branch's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#if (1)
  #declare A = 1;
#else
  #declare A = 2;
#else
  #declare A = 3;
#end
#fopen Out "else_twice_taken.out" write
#write (Out, "A = ", A, "\n")
#fclose Out

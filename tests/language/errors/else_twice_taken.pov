// Two #else branches after a taken #if branch.
#version 3.7;
#if (1)
  #declare A = 1;
#else
  #declare A = 2;
#else
  #declare A = 3;
#end

// Two #else branches in one #if.
#version 3.7;
#if (0)
  #declare A = 1;
#else
  #declare A = 2;
#else
  #declare A = 3;
#end

// Error test: an #if whose #end is missing; the file ends inside it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare A = 1;
#if (A > 0)
  #declare B = 2;
#else
  #declare B = 3;

#declare C = 4;

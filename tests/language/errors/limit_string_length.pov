// Error test: a string that doubles in a loop stops at the string length
// limit (16 MiB) instead of exhausting the memory.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare S = "x";
#while (1)
  #declare S = concat(S, S);
#end

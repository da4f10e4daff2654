// Error test: the error is in a macro body; the message points into the body.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#macro Ratio(A, B)
  (A / B + Offset)
#end
#declare R = Ratio(1, 2);

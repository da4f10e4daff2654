// Error test: a macro invoked with the wrong number of parameters.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#macro Area(W, H)
  (W * H)
#end
#declare A = Area(3, 4, 5);

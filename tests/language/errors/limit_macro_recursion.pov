// Error test: a macro that calls itself without end stops at the limit of
// macro calls in progress (200).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#macro Forever(N)
  Forever(N + 1)
#end
#declare X = Forever(0);

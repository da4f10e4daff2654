// Error test: a #while that never ends stops after Max_Parse_Iterations
// loop iterations (limit_parse_iterations.options lowers it to 1000).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare I = 0;
#while (I < 10)
  #declare J = I;
#end

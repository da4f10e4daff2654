// Pre-3.5 scenes declare floats without ';'. A loop of such declarations
// must run as a loop (not one nesting level per iteration): 20 000
// iterations, and a vector item read right before a directive.
#version 3.1;
global_settings { assumed_gamma 1.0 }
#declare I = 0
#declare S = 0
#while (I < 20000)
  #declare S = S + I
  #declare I = I + 1
#end
#declare V = <1, 2, 3>
#declare W = V.y
#fopen Out "declare_loop_no_semicolon.out" write
#write (Out, "S = ", str(S, 0, 0), " I = ", I, " W = ", W, "\n")
#fclose Out

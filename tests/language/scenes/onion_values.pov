// onion's values through a pattern function: the pattern wraps the
// distance itself, so a distance of exactly 1, 2 or 3 gives 0 (not the
// map's last colour) and 2.5 gives exactly 0.5 (textures/pigments/
// cantelop.pov's rind at radius 1).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Onion = function { pattern { onion } }
#fopen Out "onion_values.out" write
#for (I, 0, 12)
  #local R = I * 0.25;
  #write (Out, "r ", str(R, 0, 3), ": ", str(Onion(R, 0, 0), 0, 8), " ", str(Onion(0, R, 0), 0, 8), " ",
          str(Onion(R * 0.6, 0, R * 0.8), 0, 8), "\n")
#end
#write (Out, "just above 1: ", str(Onion(1.000001, 0, 0), 0, 8), " just below 1: ", str(Onion(0.9999999, 0, 0), 0, 8), "\n")
#fclose Out

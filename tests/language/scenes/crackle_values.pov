// crackle's values at parse time through pattern functions: the feature
// points (form <1,0,0> gives the distance to the nearest), the default
// form, metrics 1 and 3, offset, solid cells and the clamp to [0, 1].
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Nearest = function { pattern { crackle form <1,0,0> } }
#declare Default = function { pattern { crackle } }
#declare Metric1 = function { pattern { crackle metric 1 } }
#declare Metric3 = function { pattern { crackle metric 3 offset 0.2 } }
#declare Solid = function { pattern { crackle solid } }
#declare Weights = function { pattern { crackle form <0.3,0.5,0.7> } }
#declare Negative = function { pattern { crackle form <1,-1,0> } }
#declare S = seed(11);
#fopen Out "crackle_values.out" write
#for (I, 0, 24)
  #local P = <rand(S) * 200 - 100, rand(S) * 200 - 100, rand(S) * 200 - 100>;
  #write (Out, "point ", I, ": nearest ", str(Nearest(P.x, P.y, P.z), 0, 6), " default ", str(Default(P.x, P.y, P.z), 0, 6),
          " metric1 ", str(Metric1(P.x, P.y, P.z), 0, 6), " metric3 ", str(Metric3(P.x, P.y, P.z), 0, 6),
          " solid ", str(Solid(P.x, P.y, P.z), 0, 6), " weights ", str(Weights(P.x, P.y, P.z), 0, 6),
          " negative ", str(Negative(P.x, P.y, P.z), 0, 6), "\n")
#end
#fclose Out

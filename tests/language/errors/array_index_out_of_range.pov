// Error test: an array index past the end of the array.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Values = array[3] {1, 2, 3}
#declare Sum = 0;
#for (I, 0, 3)
  #declare Sum = Sum + Values[I];
#end

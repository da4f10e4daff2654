// Error test: reading an array element that was never assigned.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Values = array[4];
#declare Values[0] = 1;
#declare First = Values[0];
#declare Second = Values[1];

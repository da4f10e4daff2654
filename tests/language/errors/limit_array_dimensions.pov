// Error test: dimensions that are each allowed but whose product is too
// large are refused before allocating.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare A = array[10000][10000];

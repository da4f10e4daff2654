// Error test: a huge array is refused before anything is allocated
// (povray 3.7 hangs on this declaration).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare A = array[1e9];

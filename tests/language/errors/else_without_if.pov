// Error test: an #else with no #if, #ifdef, #ifndef or #switch open.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare A = 1;
#else
#declare A = 2;

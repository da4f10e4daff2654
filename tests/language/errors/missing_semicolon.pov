// Error test: a float declaration without its semicolon (needed since 3.5).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare A = 1
#declare B = 2;

// Error test: a block comment that is never closed.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare A = 1;
/* this comment is not closed
#declare B = 2;

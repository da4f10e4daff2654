// Error test: the error is in an included file; the message must name it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Before = 1;
#include "error_in_include.inc"

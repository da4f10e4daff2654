// Error test: an include file that does not exist.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "no_such_file.inc"

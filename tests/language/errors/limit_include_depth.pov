// Error test: a file that includes itself stops at the limit of open
// include files (100).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "limit_include_depth.inc"

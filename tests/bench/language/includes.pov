// Benchmark (c): parsing the standard include files.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "math.inc"
#include "functions.inc"
#include "strings.inc"

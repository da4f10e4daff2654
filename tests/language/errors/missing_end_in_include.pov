// An include file that leaves an #if open.
#version 3.7;
#include "missing_end_in_include.inc"

// An error in a file included from an include file: the chain is shown.
#version 3.7;
#include "error_in_nested_include_a.inc"

#version 3.7;
// A folder is not a file to include.
#include "."

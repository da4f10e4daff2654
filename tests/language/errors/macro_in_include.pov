// A macro from an include file fails when called: the chain is shown.
#version 3.7;
#include "macro_in_include.inc"
#declare A = Scaled(2);

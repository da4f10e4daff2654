// Error test: povray reads comparisons only inside parentheses, so after
// `1` the declaration ends and the '<' is left over.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare F = 1 < 2;

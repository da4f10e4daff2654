// Error test: povray 3.7 never redeclares a function identifier (not even
// with #local inside a macro) until it is #undef'd.
#version 3.7;
#declare Height = function { y }
#declare Height = function { y * 2 }

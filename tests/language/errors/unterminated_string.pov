// Error test: a string literal without its closing quote.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Greeting = "Hello;
#declare A = 1;

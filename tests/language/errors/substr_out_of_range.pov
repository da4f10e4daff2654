// Error test: substr() reaching past the end of the string.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Word = "short";
#declare Part = substr(Word, 3, 10);

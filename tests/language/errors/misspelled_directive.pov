// A misspelled directive.
#version 3.7;
#delcare A = 1;

// A misspelled declared identifier.
#version 3.7;
#declare Radius = 1;
sphere { 0, Raduis }

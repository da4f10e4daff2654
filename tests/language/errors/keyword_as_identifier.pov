// A reserved word cannot be declared.
#version 3.7;
#declare sphere = 1;

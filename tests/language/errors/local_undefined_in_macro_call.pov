// An undeclared identifier passed to a macro by reference.
#version 3.7;
#macro Set(V) #declare V = 1; #end
Set(Unknown)

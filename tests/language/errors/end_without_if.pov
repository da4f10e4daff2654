// An #end that closes nothing.
#version 3.7;
#declare A = 1;
#end

// A built-in function given too many arguments.
#version 3.7;
#declare A = sqrt(4, 9);

// A vector literal with six components.
#version 3.7;
#declare V = <1, 2, 3, 4, 5, 6>;

// A character that starts no token.
#version 3.7;
#declare A = 1 @ 2;

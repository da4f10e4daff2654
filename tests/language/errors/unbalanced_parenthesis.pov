// A parenthesis that is never closed.
#version 3.7;
#declare A = (1 + 2;

#version 3.7;
// povray: "sqrt of negative number -1.000000".
#declare A = 1 + sqrt(-1);

#version 3.7;
// povray: "log of negative number -1.000000".
#declare A = log(-1);

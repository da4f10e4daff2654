#version 3.7;
// povray: "ln of negative number 0.000000".
#declare A = ln(0);

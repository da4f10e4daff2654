// A number with two decimal points.
#version 3.7;
#declare A = 1.2.3;

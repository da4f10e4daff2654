// A float where a string is expected.
#version 3.7;
#declare S = concat("a", 1);

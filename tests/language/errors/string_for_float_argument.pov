// A string where a float is expected.
#version 3.7;
sphere { 0, "one" }

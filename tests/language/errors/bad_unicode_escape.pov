// A \u escape with fewer than four hexadecimal digits.
#version 3.7;
#declare S = "caf\u00e";

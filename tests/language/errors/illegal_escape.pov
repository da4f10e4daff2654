// Error test: an escape the language does not define, in a string
// expression (povray 3.7: "Illegal escape sequence in string"). File names
// keep their backslashes instead: #include "dir\x.inc" looks for that file.
#version 3.7;
#declare Path = "C:\scenes\sky.inc";

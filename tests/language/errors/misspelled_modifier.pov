// A misspelled object modifier.
#version 3.7;
sphere { 0, 1 pigmnt { rgb 1 } }

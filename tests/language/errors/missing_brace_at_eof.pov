// The file ends inside an object.
#version 3.7;
sphere { 0, 1

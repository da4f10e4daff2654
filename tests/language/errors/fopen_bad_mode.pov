// #fopen with a mode that is not read, write or append.
#version 3.7;
#fopen F "data.txt" readwrite

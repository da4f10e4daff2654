// #fopen of a file that does not exist.
#version 3.7;
#fopen F "no_such_data.txt" read

// #read past the end of a data file leaves the variable undefined.
#version 3.7;
#fopen F "read_past_end.data" read
#read (F, A, B)
#read (F, C)
#declare D = C;

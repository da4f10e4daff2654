// #write to a file opened for reading.
#version 3.7;
#fopen F "write_to_read_file.pov" read
#write (F, "x")

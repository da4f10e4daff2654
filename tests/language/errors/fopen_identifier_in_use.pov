#version 3.7;
// povray: "Expected 'undeclared identifier', file identifier found".
#fopen F "fopen_identifier_in_use.pov" read
#fopen F "fopen_identifier_in_use.pov" read

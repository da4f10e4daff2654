// #declare with nothing after the equals sign.
#version 3.7;
#declare A = ;

// A #while loop the file never closes.
#version 3.7;
#declare I = 0;
#while (I < 3)
  #declare I = I + 1;

// More initial values than the array holds.
#version 3.7;
#declare A = array[2] {1, 2, 3}

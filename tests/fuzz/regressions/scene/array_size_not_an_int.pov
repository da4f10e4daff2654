#declare A = array[1e20];
#declare B = array[5];
#declare C = B[1e300];

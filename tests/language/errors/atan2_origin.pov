#version 3.7;
// povray: "Domain error in atan2!".
#declare A = atan2(0, 0);

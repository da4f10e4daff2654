#version 3.7;
plane { y, 0 pigment { tiling 28 } }

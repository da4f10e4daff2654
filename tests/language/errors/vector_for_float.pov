// A vector where a float is expected.
#version 3.7;
#declare A = sqrt(<1, 2, 3>);

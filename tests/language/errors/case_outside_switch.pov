// #case outside any #switch.
#version 3.7;
#case (1)

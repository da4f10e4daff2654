// A macro called with fewer arguments than it has parameters.
#version 3.7;
#macro Area(W, H) (W * H) #end
#declare A = Area(3);

// fractal colouring types are 0 to 6.
#version 3.7;
global_settings { assumed_gamma 1 }
sphere { 0, 1 pigment { mandel 20 interior 7, 1 } }

// Error test: an sRGB colour before assumed_gamma has been set.
#version 3.7;
#declare Skin = color srgb <0.9, 0.7, 0.6>;
global_settings { assumed_gamma 1.0 }

// Error test: using an identifier that was never declared.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Width = 4;
#declare Area = Width * Heigth;

// Error test: a string where a float is expected.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Name = "ten";
#declare Value = 2 * Name;

// Error test: str() asked for a billion-character field is refused before
// formatting it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare S = str(1, 1e9, 0);

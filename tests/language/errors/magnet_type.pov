// magnet types are 1 and 2 (povray rejects others).
#version 3.7;
global_settings { assumed_gamma 1 }
sphere { 0, 1 pigment { magnet 3 mandel 20 } }

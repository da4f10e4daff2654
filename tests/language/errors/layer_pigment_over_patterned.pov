// povray 3.7 refuses loose texture items on an object whose texture is
// patterned, with its message for layering.
#version 3.7;
global_settings { assumed_gamma 1.0 }
sphere { 0, 1
  texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }
  finish { phong 1 } }

// Error test: the #error directive stops parsing with its message.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Size = -1;
#if (Size < 0)
  #error concat("Size must be positive, got ", str(Size, 0, 1))
#end

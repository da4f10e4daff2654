// Language test: built-in identifiers: constants, clock and frame values of
// a still image, image size, version and #version, input_file_name.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "builtins.out" write

#write (Out, "pi ", str(pi, 0, 15), "\n")
#write (Out, "true yes on ", true, " ", yes, " ", on, "\n")
#write (Out, "false no off ", false, " ", no, " ", off, "\n")
#write (Out, "constants in expressions ", true + yes + on, " ", !off, " ", (on & !no), "\n")
#write (Out, "clock ", clock, "\n")
#write (Out, "clock_delta ", clock_delta, "\n")
#write (Out, "clock_on ", clock_on, "\n")
#write (Out, "frame_number ", frame_number, "\n")
#write (Out, "initial_clock ", initial_clock, " final_clock ", final_clock, "\n")
#write (Out, "initial_frame ", initial_frame, " final_frame ", final_frame, "\n")
#write (Out, "image_width ", image_width, " image_height ", image_height, "\n")
#write (Out, "aspect ", image_width / image_height, "\n")
#if (clock_on = 0)
  #write (Out, "clock_on = 0: still image\n")
#else
  #write (Out, "clock_on != 0: animation\n")
#end

// version and #version
#write (Out, "version ", version, "\n")
#local Temp_Vers = version;
#version 3.5;
#write (Out, "version after #version 3.5 ", version, "\n")
#version 3.1;
#write (Out, "version after #version 3.1 ", version, "\n")
#version Temp_Vers;
#write (Out, "version restored ", version, "\n")
#write (Out, "version comparisons ", (version >= 3.7), " ", (version < 3.8), "\n")

// input_file_name is the scene's file name
#write (Out, "input_file_name [", input_file_name, "]\n")
#write (Out, "input_file_name length ", strlen(input_file_name), "\n")
#fclose Out

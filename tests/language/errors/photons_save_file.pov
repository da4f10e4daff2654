// Error test: save_file may not write outside the scene's, the working and
// the output folders (File_Restrictions, as #fopen write).
#version 3.7;
global_settings { photons { spacing 0.05 save_file "/etc/frameray_map.ph" } }

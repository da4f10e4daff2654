// Error test: writing the photon map to a file (save_file) is not done yet;
// frameray stops rather than render without writing it.
#version 3.7;
global_settings { photons { spacing 0.05 save_file "map.ph" } }

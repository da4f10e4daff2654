// Error test: reading a photon map from a file (load_file) is not done yet;
// frameray stops rather than shoot photons of its own instead.
#version 3.7;
global_settings { photons { spacing 0.05 load_file "map.ph" } }

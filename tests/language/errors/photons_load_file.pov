// Error test: load_file names a photon map that is not there (povray stops
// the render with "Could not load photon map"); frameray stops at the name.
#version 3.7;
global_settings { photons { spacing 0.05 load_file "no_such_map.ph" } }

// Error test: media photons (global photons { media max_steps, factor })
// are not shot or gathered yet, so frameray stops rather than rendering the
// scene without them.
#version 3.7;
global_settings { photons { spacing 0.05 media 100, 2 } }

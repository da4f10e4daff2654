// povray applies global_settings' noise_generator to every pattern, also
// those read before it (measured: a bozo declared first changes with it);
// frameray fixes a pattern's generator as it reads it, so a change after
// a noise pattern stops rather than rendering the old generator.
#version 3.7;
#declare P = pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } }
global_settings { assumed_gamma 1.0 noise_generator 1 }
plane { z, 0 pigment { P } }

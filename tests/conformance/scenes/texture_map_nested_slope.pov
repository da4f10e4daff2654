// A slope texture map inside a gradient texture map: povray shades the
// outer map's entries last first, and the inner slope pattern of the
// entry shaded second sees the normal the first one's bumps perturbed
// (textures/patterns/slopemt_37.pov's vegetation). The outer entries are
// the same texture, so any difference between them comes from that.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -4> look_at 0 angle 45 }
light_source { <-5, 5, -10> rgb 1 }
#declare Bumpy = texture { pigment { rgb <1, 0.2, 0> } normal { bumps 1 scale 0.1 } finish { ambient 0.3 } }
#declare Plain = texture { pigment { rgb <0, 0.3, 1> } finish { ambient 0.3 } }
#declare Slope = texture { slope { y } texture_map { [0.5 Bumpy] [0.5 Plain] } }
sphere { 0, 1 texture { gradient x texture_map { [0 Slope] [1 Slope] } } }
sphere { <1.6, -0.3, 0.5>, 0.7 texture { gradient x texture_map { [0 Slope] [1 Plain] } scale 0.5 } }

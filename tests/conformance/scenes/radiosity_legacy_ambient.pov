// A scene before 3.7 under radiosity: `ambient` still makes surfaces glow,
// and the glow lights the others (measured; 3.7 scenes ignore ambient).
#version 3.6;
global_settings { assumed_gamma 1 radiosity { count 60 recursion_limit 1 pretrace_start 0.1 pretrace_end 0.05 } }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
sphere { 0, 10000 hollow texture { pigment { rgb <0.6, 0.7, 1> } finish { diffuse 0 ambient 0.8 } } }
plane { y, 0 texture { pigment { rgb <0.9, 0.8, 0.6> } finish { diffuse 0.5 ambient 0.2 } } }

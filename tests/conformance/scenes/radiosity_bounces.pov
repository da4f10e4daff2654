// Light bouncing between two facing planes: the lower glows (emission) and
// both reflect diffusely; recursion_limit 3 lets the light bounce three
// times (measured: the deepest surface reached adds no radiosity).
#version 3.7;
global_settings { assumed_gamma 1 radiosity { count 50 recursion_limit 3 pretrace_start 0.1 pretrace_end 0.05 } }
camera { location <0, 0.5, -2> look_at <0, 0, 0> angle 60 }
plane { y, 0 texture { pigment { checker rgb <1, 0.9, 0.8> rgb <0.5, 0.6, 0.7> }
                       finish { diffuse 0.5 emission 0.2 ambient 0 } } }
plane { -y, -1 texture { pigment { rgb <0.8, 0.9, 1> } finish { diffuse 0.7 emission 0 ambient 0 } } }

// Two facing mirrors: max_trace_level cuts the infinite corridor (black
// beyond it), adc_bailout cuts weak rays early.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 adc_bailout 0.05 }
camera { location <0.3, 1.2, -3> look_at <0, 1, 3> angle 60 }
light_source { <0, 5, 0> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb <0.3, 0.4, 0.7> scale 0.5 } }
plane { z, 3 pigment { rgb <0.6, 0.7, 0.6> } finish { ambient 0 diffuse 0.1 reflection 0.85 } }
plane { z, -4 pigment { rgb <0.7, 0.6, 0.6> } finish { ambient 0 diffuse 0.1 reflection 0.75 } }
sphere { <0, 1, 1>, 0.5 pigment { rgb <0.9, 0.5, 0.1> } finish { reflection 0.3 } }
sphere { <-1, 0.5, 0>, 0.3 pigment { rgb <0.2, 0.8, 0.3> } }

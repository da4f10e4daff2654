// Conformance: ripples and waves normals with frequency and phase.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { rgb <0.5, 0.6, 0.8> } normal { ripples 0.7 scale 0.6 } finish { phong 0.5 } }
sphere { <-2.4, 1, 0>, 1 pigment { rgb 0.9 } normal { waves 0.8 scale 0.2 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.4, 0.6, 1> } normal { ripples 1 frequency 3 phase 0.3 scale 0.5 } }
sphere { <2.4, 1, 0>, 1 pigment { rgb <1, 0.5, 0.3> } normal { waves 1 frequency 2 phase 0.5 } }

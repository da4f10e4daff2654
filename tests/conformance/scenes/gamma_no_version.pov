// No #version and no assumed_gamma: povray 3.7 turns gamma correction off
// as for a pre-3.7 scene (its warning says so), unless the Version option
// names one; frameray used 3.7's assumed_gamma 1.0.
global_settings { max_trace_level 5 }
camera { location <0, 0, -5> look_at 0 }
background { rgb <0.1, 0.2, 0.5> }
light_source { <5, 5, -5> rgb 1 }
sphere { -1.6*x, 1.2 pigment { rgb <0.8, 0.5, 0.2> } }
sphere { 1.6*x, 1.2 pigment { rgbf 0.9 } finish { phong 0.5 } }
plane { y, -1.2 pigment { checker rgb 0.2 rgb 0.8 } }

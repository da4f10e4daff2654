// Reflection-heavy: a grid of mirror spheres over a reflective checker floor.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 6, -12> look_at <0, 0.5, 0> angle 50 }
light_source { <-10, 20, -15> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb <0.2, 0.3, 0.6> } finish { reflection 0.3 } }
#for (i, -3, 3) #for (j, -2, 3)
  sphere { <i * 1.6, 0.7, j * 1.6>, 0.7 pigment { rgb <0.8, 0.6 + 0.05 * i, 0.4> } finish { reflection 0.8 phong 0.8 metallic } }
#end #end

// Many lights: 24 coloured point lights with shadows over a field of spheres.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 8, -12> look_at <0, 0, 0> angle 50 }
#for (k, 0, 23)
  light_source { <8 * cos(k * pi / 12), 4 + mod(k, 3), 8 * sin(k * pi / 12)> rgb <0.1 + 0.1 * mod(k, 3), 0.1 + 0.05 * mod(k, 4), 0.15> }
#end
plane { y, 0 pigment { rgb 0.8 } }
#for (i, -4, 4) #for (j, -3, 3)
  sphere { <i * 1.2, 0.4, j * 1.2>, 0.4 pigment { rgb <0.9, 0.8, 0.7> } finish { phong 0.4 } }
#end #end

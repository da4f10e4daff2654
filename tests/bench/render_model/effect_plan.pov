// Effect plan: a diffuse scene, rendered once as it is and once with
// Declare=UnusedEffects=1, which adds a reflective, refracting glass sphere
// behind the camera that no camera, shadow or reflected ray can reach
// (no_image, and out of every light path). The two runs' times must stay
// within 2 %: effects a scene declares but never shows cost nothing.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -10> look_at <0, 0.5, 0> angle 50 }
light_source { <-8, 12, -6> rgb 0.8 }
light_source { <6, 9, -8> rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.85 rgb 0.6 } }
#for (i, -4, 4) #for (j, -2, 2)
  sphere { <i * 1.1, 0.45, j * 1.1>, 0.45
    pigment { rgb <0.5 + 0.05 * i, 0.6, 0.5 - 0.05 * j> } finish { phong 0.3 } }
#end #end
#ifdef (UnusedEffects)
  sphere { <0, 4, -30>, 1
    pigment { rgbf <1, 1, 1, 0.9> }
    finish { reflection { 0.2, 1 fresnel } specular 0.8 }
    interior { ior 1.5 }
    no_image }
#end

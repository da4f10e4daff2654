// interior { caustics C }: povray's fake caustics brighten light passing
// through a transparent surface by 1 + |cos|^(45 C), cos between the
// shadow ray and the (perturbed) surface normal: bright spots in the
// shadows of glass spheres, a bumpy sheet and a filtering box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -8> look_at <0, 0.6, 0> angle 45 }
light_source { <2, 12, -4> rgb 1 }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <-2.2, 1, 0>, 1 pigment { rgbf <0.9, 0.95, 1, 0.9> } finish { ambient 0 diffuse 0.1 phong 0.5 }
  interior { ior 1.5 caustics 1 } }
sphere { <0.2, 0.8, -0.5>, 0.8 pigment { rgbt <1, 0.9, 0.7, 0.8> } finish { ambient 0 diffuse 0.1 }
  interior { ior 1.3 caustics 0.4 } }
box { <1.5, 0.5, -0.5>, <3, 2, 1> pigment { rgbf <0.6, 1, 0.7, 0.7> } finish { diffuse 0.2 }
  normal { bumps 0.4 scale 0.3 } interior { caustics 0.7 } }

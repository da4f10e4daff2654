// Subsurface light transport through thin objects lit from behind: a
// slab and a sphere between the camera and a light, with a wax-like and
// a marble-like material (povray 3.7's subsurface { } model).
#version 3.7;
global_settings { assumed_gamma 1.0 mm_per_unit 20 subsurface { samples 100, 30 } }
camera { location <0, 1, -5> look_at <0, 0.8, 0> angle 40 }
light_source { <2, 4, 8> color rgb 1.5 }
light_source { <-6, 6, -6> color rgb 0.3 }
plane { y, 0 pigment { rgb 0.5 } }
box { <-1.6, 0, -0.05>, <-0.2, 1.6, 0.05>
  pigment { rgb <0.9, 0.7, 0.3> }
  finish { diffuse 0.7 subsurface { translucency <8, 5, 2> } }
  interior { ior 1.4 }
}
sphere { <0.9, 0.6, 0>, 0.6
  pigment { rgb <0.85, 0.8, 0.75> }
  finish { diffuse 0.9 specular 0.3 subsurface { translucency <2, 1.5, 1> } }
  interior { ior 1.5 }
}

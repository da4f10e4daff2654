// A wax-like sphere and a marble-like box under two lights: povray 3.7's
// subsurface light transport (diffuse dipole, single scattering, unscattered).
#version 3.7;
global_settings { assumed_gamma 1.0 mm_per_unit 40 subsurface { samples 200, 20 } }
camera { location <0, 1.5, -4> look_at <0, 0.6, 0> angle 45 }
light_source { <-20, 30, -15> color rgb 1 }
light_source { <20, 5, 20> color rgb 0.5 }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <-0.7, 0.6, 0>, 0.6
  pigment { rgb <0.8, 0.5, 0.01> }
  finish { diffuse 0.6 subsurface { translucency <5, 3, 1>*0.5 } }
  interior { ior 1.45 }
}
box { <0.2, 0, -0.5>, <1.2, 1, 0.5>
  pigment { rgb <0.83, 0.79, 0.75> }
  finish { diffuse 0.8 specular 0.4 subsurface { translucency <0.4562, 0.3811, 0.3325> } }
  interior { ior 1.5 }
  rotate y*30
}

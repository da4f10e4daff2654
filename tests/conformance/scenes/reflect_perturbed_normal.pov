// Mirror rays from strongly perturbed normals: where the reflected ray
// would go under the surface povray mirrors the view ray about the
// geometric normal, or the reflected ray back above the surface
// (textures.inc's Brushed_Aluminum and Water are such textures).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <-30, 40, -60> rgb 1 }
background { rgb <0.25, 0.3, 0.4> }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.3 } }
sphere { <-1.2, 0.6, 0>, 1
  pigment { rgb <0.6, 0.6, 0.65> }
  finish { ambient 0.3 diffuse 0.7 reflection 0.85 brilliance 8 specular 0.8 roughness 0.1 }
  normal { bumps -0.5 scale <1, 0.001, 0.001> } }
sphere { <1.2, 0.6, 0>, 1
  pigment { rgb <0.7, 0.5, 0.3> }
  finish { reflection { 0.3, 1 fresnel } conserve_energy }
  normal { ripples 1.5 frequency 10 }
  interior { ior 1.33 } }

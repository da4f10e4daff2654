// Photon mapping: caustics from mirrors: a tilted flat mirror throws a
// patch of light onto a wall, and a polished metal ring makes the
// cardioid-like caustic on the floor inside it. The mirror's caustic is
// as bright as the light head-on (povray's lights do not fade, nor do
// their photons).
#version 3.7;
global_settings {
  assumed_gamma 1.0
  photons { spacing 0.01 jitter 0 autostop 0 }
}
camera { location <0, 7, -7> look_at <0, 0.5, 0.5> angle 45 }
light_source { <-6, 6, -2>, rgb 0.9 photons { refraction off reflection on } }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.05 diffuse 0.7 } }
plane { z, 4 pigment { rgb 0.7 } finish { ambient 0.05 diffuse 0.7 } }
difference {
  cylinder { <0, 0, 0>, <0, 0.8, 0>, 2 }
  cylinder { <0, -1, 0>, <0, 1, 0>, 1.9 }
  pigment { rgb <0.9, 0.8, 0.5> }
  finish { ambient 0 diffuse 0.1 reflection { 0.9 metallic } }
  photons { target reflection on collect off }
}
box { <-0.6, -0.6, -0.05>, <0.6, 0.6, 0.05>
  rotate <0, 60, 0> translate <2.8, 1.5, 2>
  pigment { rgb 1 } finish { ambient 0 diffuse 0 reflection 1 }
  photons { target reflection on collect off }
}

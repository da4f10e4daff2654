// Accuracy study: photon mapping (issue 27). A glass sphere's refracted
// caustic and a ring mirror's reflected caustic (the cardioid) on a
// matte floor: the caustics exist only through photons, so the spacing
// and the gather count decide their noise and blur.
// study-knobs: photons_spacing photons_gather photons_jitter
// study-baseline: -A Declare=PhotonSpacing=0.05 Declare=PhotonGatherMax=100 Declare=PhotonJitter=0.4
// study-reference: -A Declare=PhotonSpacing=0.0025 Declare=PhotonGatherMax=100 Declare=PhotonJitter=0.4
#version 3.7;
#ifndef (PhotonSpacing) #declare PhotonSpacing = 0.05; #end
#ifndef (PhotonGatherMax) #declare PhotonGatherMax = 100; #end
#ifndef (PhotonJitter) #declare PhotonJitter = 0.4; #end
global_settings {
  assumed_gamma 1.0
  max_trace_level 10
  photons { spacing PhotonSpacing gather 20, PhotonGatherMax jitter PhotonJitter autostop 0 }
}
camera { location <0, 6, -7> look_at <0, 0.4, 0.3> angle 45 }
light_source { <-4, 8, -2>, rgb 1 photons { refraction on reflection on } }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.05 diffuse 0.7 } }
sphere { <-1.4, 1, 0.5>, 0.9
  pigment { rgbf <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 reflection 0.05 specular 0.6 roughness 0.005 }
  interior { ior 1.5 }
  photons { target refraction on reflection on collect off } }
difference {
  cylinder { <0, 0, 0>, <0, 0.6, 0>, 1.3 }
  cylinder { <0, -1, 0>, <0, 1, 0>, 1.22 }
  translate <1.4, 0, 0.6>
  pigment { rgb <0.9, 0.8, 0.5> }
  finish { ambient 0 diffuse 0.1 reflection { 0.9 metallic } }
  photons { target reflection on collect off } }

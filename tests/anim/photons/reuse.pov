// Photon maps across frames: with Reuse=1 (Declare) the first frame
// shoots and saves its photons (save_file), the later ones load them
// (load_file) instead of shooting; the light and the glass stay put while
// the camera moves, so every frame must match a run that shoots in every
// frame, byte for byte.
#version 3.7;
#ifndef (Reuse) #declare Reuse = 0; #end
global_settings {
  assumed_gamma 1.0
  max_trace_level 8
  photons {
    spacing 0.02
    #if (Reuse)
      #if (frame_number = 1) save_file "reuse.ph" #else load_file "reuse.ph" #end
    #end
  }
}
camera { location <clock * 2 - 1, 4, -5> look_at <0, 0.6, 0> angle 45 }
light_source { <2, 8, 1>, rgb 1 photons { refraction on reflection on } }
plane { y, 0 pigment { rgb 0.7 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-0.6, 1, 0>, 0.8
  pigment { rgbf <1, 0.95, 0.9, 0.95> }
  finish { ambient 0 diffuse 0 reflection 0.1 }
  interior { ior 1.5 }
  photons { target refraction on reflection on collect off } }
box { <-0.5, -0.5, -0.05>, <0.5, 0.5, 0.05> rotate <0, 30, 20> translate <1.2, 1, 0.5>
  pigment { rgb 1 } finish { ambient 0 diffuse 0 reflection 1 }
  photons { target 0.7 reflection on collect off } }

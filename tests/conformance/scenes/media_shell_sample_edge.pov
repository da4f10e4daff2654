// A shell of scattering media around the camera, lit by a light outside
// it. Method 3's first point of each camera ray's stretch lies on the
// shell's inner surface; where the way from it to the light dips back
// into the hollow, povray 3.7 dims the light over the hollow only (the
// shadow ray keeps the camera ray's containers and toggles them at each
// crossing), which lights a wedge of the shell toward the light.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0.03, 0.03, 0.02>
  sky z up z right -x*image_width/image_height direction y
  look_at <-1, -1, 0.1>
  angle 60
}
light_source { <-0.7, 0.83, 0.24>*15 color rgb <3.4, 2.9, 2.0> }
difference {
  sphere { 0, 5 }
  sphere { 0, 3.5 }
  pigment { rgbf 1 }
  finish { ambient 0 diffuse 0 }
  interior {
    media {
      scattering { 1, <5, 4.6, 3.1> extinction 0.77 }
      method 3 samples 10, 10 intervals 1
    }
  }
  hollow
}
// The same shell's media sampled with a density, lower down.
difference {
  sphere { 0, 5 }
  sphere { 0, 3.5 }
  pigment { rgbf 1 }
  finish { ambient 0 diffuse 0 }
  interior {
    media {
      scattering { 1, <5, 4.6, 3.1> extinction 0.77 }
      method 3 samples 10, 10 intervals 2
      density { wrinkles color_map { [0 rgb 0] [0.4 rgb 0] [1 rgb 1] } scale 0.7 }
    }
  }
  hollow
  scale <1, 1, 0.6>
  translate -3.2*z
}

// Conformance: a fine-stepped julia_fractal (precision 400) shadowing
// itself. povray's fractal reports only its first crossing from the ray's
// own start, and a shadow ray drops crossings nearer than 1e-3: a shadow
// ray leaving the surface meets the surface it leaves and so nothing, even
// where the march would find more of the fractal past 1e-3.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, 0> up <0, 0, 1> right x * 4 / 3 sky <0, 0, 1> look_at 0 }
light_source { <3, 4, 9> rgb <1, 0.95, 0.9> }
light_source { <-5, 4, -9> rgb <1, 0.9, 0.6> * 0.5 }
background { rgb <0.9, 0.92, 1> }
julia_fractal { <0.45, 0.52, -0.3, 0.12> quaternion max_iteration 7 precision 400
  pigment { rgb <0.7, 0.9, 0.5> } finish { ambient 0.1 diffuse 0.9 phong 1 phong_size 300 }
  rotate <100, 40, -50> }

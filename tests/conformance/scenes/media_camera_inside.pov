// A camera inside a hollow sphere of media wrapped in a union that has no
// interior of its own (advanced/abyss.pov's sea): camera rays start in the
// media. Constant Henyey-Greenstein scattering with `intervals 3`, which
// povray 3.7 samples over three intervals since it scatters light (a
// constant media that only emits and absorbs gets one), plus a second
// sphere of constant scattering media seen from outside.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <-20, -20, -400> angle 65 right x*image_width/image_height look_at <-20, 30, 0> }
background { rgb 0 }
light_source { <-10, 1000, -10> color rgb <7, 146, 217> / 255 * 10 }
light_source { <-20, -20, -400> color rgb 1 shadowless media_interaction off }
union {
  sphere { 0, 410 hollow
    texture { pigment { rgbt 1 } finish { ambient 0 diffuse 0 } }
    interior { media {
      scattering { 5, 0.00034 eccentricity 0.7 extinction 0.8 }
      absorption <232, 84, 16> * 0.0005 / 255
      intervals 3 } } }
  scale 4 rotate -15 * y translate <19, 5, 0>
}
sphere { <-20, 40, -250>, 30 hollow pigment { rgbt 1 }
  interior { media { scattering { 2, 0.01 } intervals 4 } } }

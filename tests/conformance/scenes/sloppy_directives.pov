// Conformance: two slips povray 3.7 accepts silently in the example scenes:
// `default { }` written without its '#' (advanced/whiltile.pov), and a '#'
// with nothing after it but a '}' (language/image_size.pov).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 2.5, -6>
  look_at <0, 0.4, 0>#
}
light_source { <4, 7, -5> rgb 1 }
default {
  texture { pigment { rgb <0.9, 0.5, 0.2> } finish { ambient 0.25 specular 0.6 } }
}
plane { y, -1 pigment { checker rgb 0.9 rgb 0.4 }# }
sphere { <-1.2, 0, 0>, 1 }
box { <0.4, -1, -0.8>, <2, 0.6, 0.8> rotate y*20 # }

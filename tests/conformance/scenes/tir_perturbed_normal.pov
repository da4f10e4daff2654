// Conformance: total internal reflection at a surface whose normal is
// perturbed. Seen from under water, the rippled surface mirrors the pool
// floor wherever it does not let the sky through; at grazing angles the
// rippled normal can send the mirrored ray up through the surface, and
// povray then mirrors it back below, as it does for a reflection.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 1, -6> look_at <0, 1.6, 4> angle 70 }
light_source { <3, 30, -4> rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.9, 1>] [1 rgb <0.2, 0.4, 0.9>] } } }
box { <-20, -3, -20>, <20, 3, 30>
  hollow
  pigment { rgbf <0.8, 0.95, 1, 0.95> }
  normal { ripples 0.35 scale 1.5 }
  interior { ior 1.33 }
}
box { <-20, -1.2, -20>, <20, -1, 30>
  pigment { checker rgb <1, 0.9, 0.6> rgb <0.2, 0.3, 0.5> scale 0.8 }
}
sphere { <1.5, 4.2, 8>, 1 pigment { rgb <1, 0.3, 0.2> } }

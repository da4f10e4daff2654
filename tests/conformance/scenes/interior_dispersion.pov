// interior { dispersion dispersion_samples }: rays bending into or out of
// a dispersive interior split into coloured bands, each refracted by its
// own ior (a prism and a lens-like sphere in front of white stripes).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 1.6, -8> look_at <0, 1.1, 0> angle 45 }
light_source { <-8, 12, -10> rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
plane { z, 6 pigment { gradient x color_map { [0 rgb 0.02] [0.85 rgb 0.02] [0.85 rgb 1] [1 rgb 1] } scale 0.8 } finish { ambient 1 diffuse 0 } }
// A prism: light bends at both faces, the bands fan out.
prism { linear_sweep linear_spline 0, 2.4, 4, <-1, 0>, <1, 0>, <0, 1.6>, <-1, 0>
  rotate -90 * x translate <-1.6, 0.3, 0>
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.5 dispersion 1.15 } }
sphere { <1.6, 1.2, 0>, 1
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 specular 0.5 roughness 0.01 }
  interior { ior 1.4 dispersion 1.08 dispersion_samples 12 } }

// An object's uv_mapping maps the texture given after it: nothing is
// layered under that texture (advanced/benchmark.pov's lathe mesh;
// frameray layered the texture over the default one and lost the uv).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -5> look_at 0 }
light_source { <5, 5, -5> rgb 1 }
background { rgb <0.1, 0.2, 0.4> }
sphere { 0, 1.6 uv_mapping
  texture { pigment { checker rgb <1, 0.7, 0.5> rgb <0, 0, 0.15> scale 0.1 } finish { specular 0.3 } } }

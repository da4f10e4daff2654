// The light reaching a surface inside a fading interior, as povray 3.7
// fades it: by the shadow ray's own way out of the interior, not by the
// camera ray's way in (measured: a lit floor under fading water darkens
// with depth only where the water casts shadows; under no_shadow water,
// or behind a no_shadow fading slab, the surface keeps its whole light).
// Cut down from advanced/benchmark/benchmark.pov's water.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0, 5, -3> look_at <0, 0, 0> angle 60 }
light_source { <-3, 10, -2> * 1000 color rgb 0.6 }
light_source { <2, 6, -6> color rgb 0.4 }
#declare Water = material {
  texture { pigment { rgbt <0.21, 0.2, 0.3, 0.96> } finish { ambient 0 diffuse 0 } }
  interior { ior 1 fade_distance 0.8 fade_power 1001 fade_color <0.02, 0.2, 0.06> }
}
plane { y, -0.8 rotate -20 * x pigment { rgb <1, 0.85, 0.6> } finish { ambient 0.02 diffuse 0.7 } }
// Left: water that casts shadows; right: no_shadow water.
box { <-4, 0, -3>, <0, -6, 3> material { Water } hollow on }
box { <0, 0, -3>, <4, -6, 3> material { Water } hollow on no_shadow }
// A diffuse fading slab above the water, its back face lit through it.
box { <-1.5, 1.2, -1.5>, <-0.3, 1.6, -0.5> pigment { rgbt <0.8, 0.9, 1, 0.7> } finish { ambient 0 diffuse 0.6 }
      interior { ior 1 fade_distance 0.3 fade_power 1 } no_shadow }
box { <0.3, 1.2, -1.5>, <1.5, 1.6, -0.5> pigment { rgbt <0.8, 0.9, 1, 0.7> } finish { ambient 0 diffuse 0.6 }
      interior { ior 1 fade_distance 0.3 fade_power 1 } }

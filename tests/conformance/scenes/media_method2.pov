// Media sampling method 2 as povray 3.7 does it (jitter 0: povray is
// deterministic): each interval's samples at (j + 0.5) / samples of it,
// each standing for the whole interval with its light dimmed by its own
// extinction over its distance from the interval's start, the intervals'
// means added front to back. Density slabs (top) with one and three
// intervals, constant slabs (bottom) with one and four (one sampled, no
// light interacts with media).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 angle 50 }
background { rgb 0 }
#declare Map = color_map { [0 rgb 1] [0.5 rgb 0.6] [0.55 rgb 0.1] [1 rgb 0.3] }
#macro Slab(Intervals, Samples, Dens)
  box { <-1.8, -1.5, -2>, <1.8, 1.5, 2> hollow pigment { rgbf 1 }
    interior { media { method 2 samples Samples intervals Intervals jitter 0
      emission <0.3, 0.2, 0.1> absorption <0.2, 0.5, 0.9>
      #if (Dens) density { gradient <1, 0, 1> frequency 2 color_map { Map } } #end } } }
#end
object { Slab(1, 4, true) translate <-2, 1.7, 0> }
object { Slab(3, 3, true) translate <2, 1.7, 0> }
object { Slab(1, 5, false) translate <-2, -1.7, 0> }
object { Slab(4, 2, false) translate <2, -1.7, 0> }

// Media sampling method 1 as povray 3.7 does it: `samples` random points
// in each interval (povray's random numbers differ from run to run, so
// the golden is matched in local means), each standing for the whole
// interval with its light dimmed by its own extinction over its distance
// from the interval's start. Density slabs (top) with one and three
// intervals, a constant slab (bottom left), and one scattering the light
// of a point light (bottom right, its shadow rays sampled too).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right 8 * x up 6 * y }
background { rgb 0 }
light_source { <2, -1.5, -6> color rgb 1 }
#declare Map = color_map { [0 rgb 1] [0.5 rgb 0.6] [0.55 rgb 0.1] [1 rgb 0.3] }
#macro Slab(Intervals, Samples, Dens, Scatter)
  box { <-1.8, -1.3, -2>, <1.8, 1.3, 2> hollow pigment { rgbf 1 }
    interior { media { method 1 samples Samples intervals Intervals
      #if (Scatter) scattering { 1, 0.3 } #else emission <0.3, 0.2, 0.1> #end
      absorption <0.2, 0.5, 0.9>
      #if (Dens) density { gradient <1, 0, 1> frequency 2 color_map { Map } } #end } } }
#end
object { Slab(1, 60, true, false) translate <-2, 1.5, 0> }
object { Slab(3, 30, true, false) translate <2, 1.5, 0> }
object { Slab(2, 40, false, false) translate <-2, -1.5, 0> }
object { Slab(2, 40, true, true) translate <2, -1.5, 0> }

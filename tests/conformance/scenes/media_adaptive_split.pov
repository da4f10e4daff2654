// Method 3's adaptive split as povray 3.7 does it: the light difference
// between an end and the middle of a sub-interval, times the interval's
// length, against aa_threshold; a half that does not differ counts as
// (2 * outer end + middle) / 3. Sharp colour-mapped densities make many
// one-sided splits: emission (top), scattering (bottom), each with one
// and with two intervals.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 angle 50 }
background { rgb 0 }
light_source { <10, 10, -10> color rgb 1 }
#declare Map = color_map { [0 rgb 1] [0.5 rgb 0.85] [0.55 rgb 0.035] [1 rgb 0.035] }
#macro Slab(Intervals, Samples, Emitting)
  box { <-1.8, -1.5, -2>, <1.8, 1.5, 2> hollow pigment { rgbf 1 }
    interior { media { samples Samples intervals Intervals
      #if (Emitting) emission 0.5 #else scattering { 1, 0.5 } #end
      density { gradient <1, 0, 1> frequency 3 color_map { Map } } } } }
#end
object { Slab(1, 4, true) translate <-2, 1.7, 0> }
object { Slab(2, 6, true) translate <2, 1.7, 0> }
object { Slab(1, 4, false) translate <-2, -1.7, 0> }
object { Slab(3, 10, false) translate <2, -1.7, 0> }

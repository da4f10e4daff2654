// Constant media (no density) are sampled over one interval whatever
// `intervals` says, unless a light that interacts with media lights the
// ray: then over the intervals asked for, as povray 3.7 does even for
// media that only emit and absorb. Left: intervals 1, right: intervals 4;
// top method 3, bottom method 2; the point light scatters in no media.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 angle 50 }
background { rgb 0 }
light_source { <10, 10, -10> color rgb 1 }
#macro Slab(Method, Intervals)
  box { <-1.8, -1.5, -2>, <1.8, 1.5, 2> hollow pigment { rgbf 1 }
    interior { media { method Method samples 3 intervals Intervals
      emission <0.3, 0.2, 0.1> absorption <0.2, 0.5, 0.9> } } }
#end
object { Slab(3, 1) translate <-2, 1.7, 0> }
object { Slab(3, 4) translate <2, 1.7, 0> }
object { Slab(2, 1) translate <-2, -1.7, 0> }
object { Slab(2, 4) translate <2, -1.7, 0> }

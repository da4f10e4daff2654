// `ratio` shares the intervals between the pieces of a ray lit by a spot
// or cylinder light and the unlit ones as povray 3.7 does: a piece gets
// floor(weight / total weight * intervals) + 1 (weight ratio when lit,
// 1 - ratio when not) but leaves one for each piece after it. A cylinder
// light's shaft along x crosses four absorbing, scattering boxes with six
// intervals and one sample (method 3 with ratio 0.1 and 0.9, method 2 with
// 0.1 and 0.6): the fewer intervals the lit piece gets, the brighter it is.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 angle 50 }
background { rgb 0 }
light_source { <-10, 0, 0> color rgb 6 cylinder point_at <0, 0, 0> radius 0.8 falloff 0.8 }
#macro Slab(Method, Ratio, Samples)
  box { <-0.9, -2, -2>, <0.9, 2, 2> hollow pigment { rgbf 1 }
    interior { media { method Method samples Samples intervals 6 ratio Ratio
      scattering { 1, 0.3 } absorption 0.6 } } }
#end
object { Slab(3, 0.1, 1) translate -3 * x }
object { Slab(3, 0.9, 1) translate -1 * x }
object { Slab(2, 0.1, 1) translate 1 * x }
object { Slab(2, 0.6, 1) translate 3 * x }

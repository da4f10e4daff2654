// `confidence` and `variance` as povray 3.7 reads them (methods 1 and 2):
// after k samples an interval takes another random one while the
// variance of its mean light exceeds variance * q(k) / q(max - 1), q(n)
// being the chi-square value n degrees of freedom exceed with probability
// `confidence`, up to samples max + 1. Constant emitting slabs, method 2,
// samples 2, 400 (the two first samples' variance of the mean: 0.013):
// top left confidence 0.5 variance 4 (threshold 0.0139: no more samples,
// povray is deterministic there), top right confidence 0.7 (threshold
// 0.0074: random samples, whose mean is the integral's), bottom left
// variance 1e-9 (random samples up to 401), bottom right method 3, which
// reads neither.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right 8 * x up 6 * y }
background { rgb 0 }
#macro Slab(Method, Confidence, Variance)
  box { <-1.8, -1.3, -2>, <1.8, 1.3, 2> hollow pigment { rgbf 1 }
    interior { media { method Method samples 2, 400 intervals 1
      confidence Confidence variance Variance
      emission <0.3, 0.2, 0.1> absorption <0.2, 0.5, 0.9> } } }
#end
object { Slab(2, 0.5, 4) translate <-2, 1.5, 0> }
object { Slab(2, 0.7, 4) translate <2, 1.5, 0> }
object { Slab(2, 0.9, 1e-9) translate <-2, -1.5, 0> }
object { Slab(3, 0.1, 1e-9) translate <2, -1.5, 0> }

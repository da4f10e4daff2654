// Language test: the special function types: spline and transform (vector)
// functions, pigment (colour) functions, pattern functions and the internal
// functions of functions.inc.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "functions_special.out" write

#macro W(Label, Value)
  #write (Out, Label, " ", str(Value, 0, 9), "\n")
#end
#macro V(Label, N, Value)
  #write (Out, Label, " ", vstr(N, Value, ",", 0, 6), "\n")
#end

// Spline functions return as many components as the spline's points
#declare foo2 = function {
  spline {
    linear_spline
    0.0, <0,0,0>
    0.5, <1,0,0>
    1.0, <0,0,0>
  }
}
V("spline function foo2(0.7)", 3, foo2(0.7))
V("spline function foo2(0.25)", 3, foo2(0.25))
#declare Curve2 = function { spline { cubic_spline 0, <0,0> 1, <1,1> 2, <2,0> 3, <3,1> } }
V("spline function 2 components", 2, Curve2(1.5))
#declare Curve5 = function { spline { linear_spline 0, <0,0,0,0,0> 1, <1,2,3,4,5> } }
V("spline function 5 components", 5, Curve5(0.5))
W("spline function dot item", foo2(0.7).x)

// Transform functions
#declare Xf = function {
  transform {
    rotate <90, 0, 0>
    scale 4
  }
}
#declare myvector = Xf(4, 3, 7);
V("transform function Xf(4,3,7)", 3, myvector)
#declare Move = function { transform { translate <1,2,3> } }
V("transform function translate", 3, Move(0, 0, 0))
#declare Inverse = function { transform { translate <1,2,3> scale 2 inverse } }
V("transform function inverse", 3, Inverse(4, 6, 8))

// Pigment functions return colours
#declare Solid = function {
  pigment {
    color red 1 green 0.5 filter 0.25
  }
}
V("pigment function solid", 5, Solid(1, 2, 3))
#declare Ramp = function { pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0.25>] } } }
V("pigment function gradient at 0.5", 5, Ramp(0.5, 0, 0))
W("pigment function gray", Ramp(0.25, 0, 0).gray)

// Pattern functions return floats
#declare Checks = function { pattern { checker } }
W("pattern checker (0.5,0.5,0.5)", Checks(0.5, 0.5, 0.5))
W("pattern checker (1.5,0.5,0.5)", Checks(1.5, 0.5, 0.5))
#declare Grad = function { pattern { gradient y } }
W("pattern gradient y (0,0.3,0)", Grad(0, 0.3, 0))
W("pattern gradient y (0,1.75,0)", Grad(0, 1.75, 0))
#declare Rings = function { pattern { onion scale 2 } }
W("pattern onion scaled (1,0,0)", Rings(1, 0, 0))

// Vector functions called inside other functions: each call takes one
// component with a dot item (.gray is the colour's luminance).
#declare RampF = function { pigment { gradient x color_map { [0 rgbft <1,0,0,0.1,0.2>] [1 rgbft <0,0.5,1,0.3,0.4>] } } }
V("pigment function gradient (0.25,0,0)", 5, RampF(0.25, 0, 0))
W("pigment function .gray", RampF(0.25, 0, 0).gray)
#declare GrayTwice = function { RampF(x, y, z).gray * 2 + RampF(x, y, z).blue }
W("function using .gray and .blue", GrayTwice(0.6, 0, 0))
#declare Turn = function { transform { rotate 90*z translate <1,2,3> } }
#declare TurnSum = function { Turn(x, y, z).y + Turn(x, y, z).z }
W("function using a transform function", TurnSum(1, 0, 0))
#declare Path = spline { cubic_spline -1, <0,0,0> 0, <1,2,3> 1, <2,0,1> 2, <4,4,4> }
#declare PathF = function { spline { Path } }
#declare PathXY = function(a) { PathF(a).x + PathF(a).y * 10 }
W("function using a spline function", PathXY(0.5))
#declare Blob = isosurface { function { 0.5 - Ramp(x, y, z).gray } contained_by { box { -1, 1 } } }
W("isosurface over a pigment function inside", inside(Blob, <0.9, 0, 0>))

// Internal functions
#include "functions.inc"
W("f_sphere(1,2,2,1)", f_sphere(1, 2, 2, 1))
W("f_torus(1,0,0,1,0.25)", f_torus(1, 0, 0, 1, 0.25))
#declare UsesInternal = function { f_sphere(x, y, z, 2) * 2 }
W("function calling f_sphere", UsesInternal(0, 3, 4))
#fclose Out

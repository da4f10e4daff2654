// Language test: splines of every type (linear, quadratic, cubic, natural),
// the type override at call time, clamping outside the parameter range,
// unordered and duplicate points, 2- to 5-component splines and spline
// identifiers.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "splines.out" write

#macro V3(V) vstr(3, V, ",", 0, 6) #end
#macro Sample(Label, S)
  #write (Out, Label, ":")
  #for (T, -0.5, 3.5, 0.25)
    #write (Out, " ", V3(S(T)))
  #end
  #write (Out, "\n")
#end

#declare Linear = spline {
  linear_spline
  0, <0,0,0>
  1, <1,2,0>
  2, <3,2,1>
  3, <3,0,-1>
}
#declare Default = spline {
  0, <0,0,0>
  1, <1,2,0>
  2, <3,2,1>
  3, <3,0,-1>
}
#declare Quadratic = spline {
  quadratic_spline
  0, <0,0,0>
  1, <1,2,0>
  2, <3,2,1>
  3, <3,0,-1>
}
#declare Cubic = spline {
  cubic_spline
  0, <0,0,0>
  1, <1,2,0>
  2, <3,2,1>
  3, <3,0,-1>
}
#declare Natural = spline {
  natural_spline
  0, <0,0,0>
  1, <1,2,0>
  2, <3,2,1>
  3, <3,0,-1>
}
Sample("linear", Linear)
Sample("default is linear", Default)
Sample("quadratic", Quadratic)
Sample("cubic", Cubic)
Sample("natural", Natural)

// Type override at call time
#write (Out, "override linear as cubic ", V3(Linear(1.5, cubic_spline)), "\n")
#write (Out, "override cubic as linear ", V3(Cubic(1.5, linear_spline)), "\n")
#write (Out, "override linear as quadratic ", V3(Linear(0.5, quadratic_spline)), " ", V3(Linear(2.5, quadratic_spline)), "\n")
#write (Out, "override linear as natural ", V3(Linear(0.5, natural_spline)), " ", V3(Linear(2.75, natural_spline)), "\n")
#write (Out, "override does not change the spline ", V3(Linear(1.5)), "\n")

// Unevenly spaced, unordered and duplicate parameters
#declare Uneven = spline {
  cubic_spline
  -1,  <0,0,0>
  0.5, <1,0,0>
  0,   <0,1,0>
  2,   <2,2,2>
  4,   <0,0,4>
  3,   <1,-1,0>
}
Sample("cubic unordered uneven", Uneven)
#declare Dup = spline {
  linear_spline
  0, <0,0,0>,
  1, <1,1,1>,
  1, <5,5,5>,
  2, <0,0,0>
}
#write (Out, "duplicate parameter replaces ", V3(Dup(1)), " ", V3(Dup(0.5)), " ", V3(Dup(1.5)), "\n")

// Vector sizes: the largest point decides
#declare Flat = spline {
  linear_spline
  0, <0,0>
  1, <2,4>
}
#write (Out, "2d spline ", Flat(0.25), " ", vstr(2, Flat(0.75), ",", 0, 3), "\n")
#declare Mixed = spline {
  linear_spline
  0, <1,2>
  1, <3,4,5>
}
#write (Out, "mixed sizes ", Mixed(0.5), "\n")
#declare ColourSpline = spline {
  linear_spline
  0, <1,0,0,0,0>
  1, <0,1,0.5,0.25,1>
}
#write (Out, "5d spline ", vstr(5, ColourSpline(0.5), ",", 0, 4), "\n")
#declare Four = spline {
  natural_spline
  0, <0,0,0,0>
  1, <1,1,1,1>
  2, <0,2,4,8>
}
#write (Out, "4d natural spline ", vstr(4, Four(0.5), ",", 0, 6), "\n")

// Spline identifiers and other uses
#declare Copy = spline { Linear }
#write (Out, "copy of a spline ", V3(Copy(2.5)), "\n")
#declare CopyCubic = spline { Linear cubic_spline }
#write (Out, "copy with another type ", V3(CopyCubic(1.5)), " original ", V3(Linear(1.5)), "\n")
#write (Out, "dot item on a spline value ", Linear(1.5).x, " ", Cubic(1.25).y, "\n")
#write (Out, "spline in an expression ", V3(Linear(0.5) * 2 + Cubic(2)), "\n")
#macro Foo(Bar, Val)
  #declare Y = Bar(Val).y;
#end
#declare myspline =
  spline {
    1, <4,5>
    3, <5,5>
    5, <6,5>
  }
Foo(myspline, 2)
#write (Out, "spline passed to a macro ", str(Y, 5, 5), "\n")
#declare Two = spline { linear_spline 0, <0,0,0> 1, <1,1,1> }
#write (Out, "two-point linear ", V3(Two(0.3)), " ", V3(Two(-1)), " ", V3(Two(2)), "\n")
#declare TwoCubic = spline { cubic_spline 0, <0,0,0> 1, <1,1,1> 2, <2,0,0> 3, <3,1,1> }
#write (Out, "four-point cubic valid range only 1..2 ", V3(TwoCubic(0.5)), " ", V3(TwoCubic(1.5)), " ", V3(TwoCubic(2.5)), "\n")
#fclose Out

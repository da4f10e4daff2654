// Where trace() meets a parametric surface, and its normal: povray 3.7
// subdivides (u, v) into pieces bounded by max_gradient from their corners
// and reports the ray's entry into the last piece's z slab (a little in
// front of the surface), the normal from the piece's lower corner. A unit
// sphere, a sheet whose max_gradient is far too small, and a Moebius strip
// with precompute (whose tabulated bounds differ from the computed ones).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Sphere = parametric {
  function { cos(u) * sin(v) } function { cos(v) } function { sin(u) * sin(v) }
  <0, 0>, <2 * pi, pi>
  contained_by { sphere { 0, 1.01 } }
  accuracy 0.002
}
#declare Sheet = parametric {
  function { 4 * u } function { 0.2 * sin(8 * u) * v } function { 4 * v }
  <-0.3, -0.3>, <0.3, 0.3>
  contained_by { box { -2, 2 } }
  max_gradient 0.01
}
#declare Strip = parametric {
  function { cos(u) + v * cos(u / 2) * cos(u) }
  function { sin(u) + v * cos(u / 2) * sin(u) }
  function { v * sin(u / 2) }
  <0, -0.3>, <2 * pi, 0.3>
  contained_by { box { -2, 2 } }
  accuracy 0.001
  precompute 12, x, y, z
  rotate <0, 33, 0>
}
#fopen Out "parametric_trace.out" write
#macro Probe(Name, Object, From, Dir)
  #local N = <0, 0, 0>;
  #local P = trace(Object, From, Dir, N);
  #write (Out, Name, " <", vstr(3, From, ", ", 0, 3), ">: <", vstr(3, P, ", ", 0, 6), "> n <",
          vstr(3, N, ", ", 0, 5), ">\n")
#end
#for (I, 0, 6)
  Probe("sphere", Sphere, <-0.6 + I * 0.2, 0.3 - I * 0.07, -5>, z)
  Probe("sphere side", Sphere, <-5, -0.5 + I * 0.15, 0.2>, <1, 0.1, 0>)
#end
Probe("sphere from inside", Sphere, <0, 0, 0>, x)
#for (I, 0, 8)
  Probe("sheet", Sheet, <-1 + I * 0.25, 3, 0.37>, -y)
#end
#for (I, 0, 8)
  Probe("strip", Strip, <-1.5 + I * 0.37, 0.2, -5>, <0, -0.05, 1>)
  Probe("strip top", Strip, <-1 + I * 0.25, 5, 0.4 - I * 0.1>, -y)
#end
#fclose Out

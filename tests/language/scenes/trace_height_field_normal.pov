// trace() on a height_field without `smooth` reports the hit triangle's
// upward normal (+y in the field's own space), whichever side the ray comes
// from, carried through the object's transformations: advanced/
// landscape.pov places its trees where vdot(N, z) > 0.85 under
// rotate -90*x scale <6, 6, -0.4>.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "trace_height_field_normal.out" write
#declare H1 = height_field { function 50, 50 { x * 0.5 + y * 0.2 } }
#declare H2 = height_field { function 50, 50 { x * 0.5 + y * 0.2 } scale <1, -1, 1> }
#declare H3 = height_field { function 50, 50 { x * 0.5 + y * 0.2 } rotate -90 * x scale <6, 6, -0.4> }
#declare H4 = height_field { function 40, 40 { sin(6 * x) * 0.3 + y * y * 0.4 } scale <2, 1, 3> rotate y * 30 }
#macro T(H, S, D, Name)
    #local N = <0, 0, 0>;
    #local P = trace(H, S, D, N);
    #write (Out, Name, " ", vstr(3, P, ",", 0, 6), " normal ", vstr(3, N, ",", 0, 6), "\n")
#end
T(H1, <0.3, 5, 0.4>, -y, "from above")
T(H1, <0.3, -5, 0.4>, y, "from below")
T(H2, <0.3, -5, 0.4>, y, "mirrored")
T(H3, <1.3, 2.4, 5>, -z, "landscape")
T(H4, <0.5, 5, 0.7>, -y, "rotated")
T(H4, <-0.3, 4, 1.2>, <0.2, -1, 0.1>, "slanted")
#fclose Out

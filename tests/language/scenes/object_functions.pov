// trace(), inside(), min_extent() and max_extent() answering from shapes.
// Normals are printed as N + 0 so a negative zero (an artefact of how each
// program happens to compute a zero component) prints as 0.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "object_functions.out" write
#declare S = sphere { <0, 0, 0>, 1 scale <2, 1, 1> translate x }
#declare B = box { <-1, -1, -1>, <1, 1, 1> rotate z * 45 }
#declare D = difference { box { -1, 1 } sphere { 0, 1.2 } }
#declare U = union { sphere { -x, 0.5 } cylinder { <0, -1, 0>, <0, 1, 0>, 0.25 } }
#declare N = <9, 9, 9>;
#declare P = trace(S, <1, 0, -5>, z, N);
#write (Out, "trace sphere ", vstr(3, P, ",", 0, 6), " normal ", vstr(3, N + 0, ",", 0, 6), "\n")
#declare P = trace(S, <-0.9, 0, -5>, z, N);
#write (Out, "trace scaled sphere edge ", vstr(3, P, ",", 0, 6), " normal ", vstr(3, N + 0, ",", 0, 6), "\n")
#declare P = trace(S, <1, 5, -5>, z, N);
#write (Out, "trace miss ", vstr(3, P, ",", 0, 6), " normal ", vstr(3, N + 0, ",", 0, 6), "\n")
#declare P = trace(B, <0, 0, -5>, <0, 0, 1>);
#write (Out, "trace rotated box ", vstr(3, P, ",", 0, 6), "\n")
#declare P = trace(D, <0.95, 0.95, -5>, z, N);
#write (Out, "trace difference corner ", vstr(3, P, ",", 0, 6), " normal ", vstr(3, N + 0, ",", 0, 6), "\n")
#declare P = trace(U, <0, 5, 0>, -y, N);
// (the cap normal's zero components are tiny non-zero values in povray)
#write (Out, "trace union from above ", vstr(3, P, ",", 0, 6), " normal is +y ", (vlength(N - y) < 1e-9), "\n")
#write (Out, "inside sphere ", inside(S, <2.5, 0, 0>), " ", inside(S, <3.5, 0, 0>), "\n")
#write (Out, "inside box ", inside(B, <1.3, 0, 0>), " ", inside(B, <0.9, 0.9, 0>), "\n")
#write (Out, "inside difference ", inside(D, <0, 0, 0>), " ", inside(D, <0.95, 0.95, 0.95>), "\n")
#write (Out, "inside union ", inside(U, <-1, 0, 0>), " ", inside(U, <0, 0.9, 0>), " ", inside(U, <0.5, 0, 0>), "\n")
#write (Out, "extent sphere ", vstr(3, min_extent(S), ",", 0, 4), " / ", vstr(3, max_extent(S), ",", 0, 4), "\n")
#write (Out, "extent union ", vstr(3, min_extent(U), ",", 0, 4), " / ", vstr(3, max_extent(U), ",", 0, 4), "\n")
#fclose Out

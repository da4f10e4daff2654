// trace() on isosurfaces: povray makes the direction unit length first (a
// direction 50 units long searches in the same steps as a unit one) and
// its root search returns the far end of the last interval shorter than
// `accuracy`, not the root: with accuracy 0.1 the point lies up to 0.1
// beyond the surface.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "trace_isosurface.out" write
#declare Wave = isosurface {
    function { y - 0.3 * sin(2 * x) * cos(3 * z) }
    contained_by { box { <-3, -1, -3>, <3, 1, 3> } }
    max_gradient 2
}
#declare Coarse = isosurface {
    function { y - 0.3 * sin(2 * x) * cos(3 * z) }
    contained_by { box { <-3, -1, -3>, <3, 1, 3> } }
    accuracy 0.1
    max_gradient 2
}
#declare Ball = isosurface {
    function { x * x + y * y + z * z - 1 + 0.1 * sin(5 * x) }
    contained_by { sphere { 0, 2 } }
    max_gradient 6
    scale <1, 0.75, 1> translate y * 0.35
}
#declare N = <9, 9, 9>;
#macro Show(Label, Obj, From, Dir)
    #declare P = trace(Obj, From, Dir, N);
    #write (Out, Label, " ", vstr(3, P, ",", 0, 7), " normal ", vstr(3, N + 0, ",", 0, 7), "\n")
#end
Show("wave unit", Wave, <0.3, 5, 0.2>, -y)
Show("wave long", Wave, <0.3, 5, 0.2>, -50 * y)
Show("wave slanted", Wave, <-2, 4, -1.5>, <1, -2, 0.7> * 30)
Show("coarse unit", Coarse, <0.3, 5, 0.2>, -y)
Show("coarse long", Coarse, <0.3, 5, 0.2>, -50 * y)
Show("coarse slanted", Coarse, <-2, 4, -1.5>, <1, -2, 0.7> * 30)
Show("ball from outside", Ball, <0.2, 0.3, -6>, z * 50)
Show("ball from above", Ball, <0.1, 9, 0.2>, -y * 3)
Show("ball from inside", Ball, <0, 0.35, 0>, <1, 1, 1>)
#fclose Out

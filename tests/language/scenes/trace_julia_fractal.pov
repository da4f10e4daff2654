// trace() on julia_fractals as povray 3.7 marches them: steps from a
// distance estimate (quaternion) or along povray's gradient (hypercomplex),
// at least 1 / precision, the hit refined to 1e-7 on the set's inside
// side; a ray from the surface point going into the set meets the
// surface it leaves first (nearer than 1e-4), so nothing; going out, the
// next surface on its way (0.000 before: the old marcher hit the point
// itself, or missed the far surface).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "trace_julia_fractal.out" write
#declare J = julia_fractal { <.49,.5,-.34,.1> quaternion max_iteration 7 precision 400 rotate <110,50,-60> }
#declare H = julia_fractal { <-.745,0,.113,.05> hypercomplex max_iteration 9 precision 20 scale <1,2,1> rotate <135,-30,0> }
#declare C = julia_fractal { <-.2,.6,.2,0> quaternion cube max_iteration 6 precision 30 }
// povray's hypercomplex cube squares (its march steps differ from sqr's).
#declare HC = julia_fractal { <-.745,0,.113,.05> hypercomplex cube max_iteration 9 precision 20 scale <1,2,1> rotate <135,-30,0> }
#macro T(F, S, D, Name)
    #local N = <0, 0, 0>;
    #local P = trace(F, S, D, N);
    #write (Out, Name, " ", vstr(3, P, ",", 0, 6), " normal ", vstr(3, N, ",", 0, 4), "\n")
    #if (vlength(N) > 0)
        #local N2 = <0, 0, 0>;
        #local Q = trace(F, P, <0.3, -1, 0.2>, N2);
        #write (Out, "  on ", vstr(3, Q, ",", 0, 6), "\n")
        #local N3 = <0, 0, 0>;
        #local R = trace(F, P, <0.3, 1, 0.2>, N3);
        #write (Out, "  back ", vstr(3, R, ",", 0, 6), "\n")
    #end
#end
#for (I, 0, 19)
    T(J, <-1.55 + I * 0.16, 3, -0.37>, -y, concat("quaternion ", str(I, 0, 0)))
    T(H, <-1.55 + I * 0.16, 3, -0.16>, -y, concat("hypercomplex ", str(I, 0, 0)))
    T(C, <-1.55 + I * 0.16, 3, 0.1>, -y, concat("cube ", str(I, 0, 0)))
    T(HC, <-1.55 + I * 0.16, 3, -0.16>, -y, concat("hypercomplex cube ", str(I, 0, 0)))
#end
#fclose Out

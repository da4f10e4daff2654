// Stability: the numerically hard cases of the swept and numerical shapes
// (issue 9), one per value of Case (tests/stability/run_speckles.sh renders
// each with and without Sturm=1 and counts NaN pixels and isolated
// speckles against the Sturm=1 render):
//   1 a bezier lathe dome with a flat tangent where it meets its axis,
//     seen straight down the axis (every ray near the axis)
//   2 the same lathe 1e4 units away, seen along its axis from 1.4e4 units
//   3 a sor closing on its axis, seen straight down the axis
//   4 an isosurface with steep gradients: pow(x, 8) + ... (|grad| up to
//     8 sqrt(3) ~ 13.9) and a sin(40 x) ripple (|grad| ~ 2.7), max_gradient
//     at the true bound
//   5 a thin isosurface shell (|r - 0.8| - 0.01: the gradient flips across
//     it) at a grazing view
// Sturm=1: lathes and sors get `sturm` (povray then solves by Sturm
// sequences; frameray's solvers are the same either way), isosurfaces
// accuracy 1e-6 and twice the max_gradient.
//
//     frameray sweep_cases.pov +W160 +H120 Declare=Case=2 Declare=Sturm=1
#version 3.7;
#ifndef (Case) #declare Case = 1; #end
#ifndef (Sturm) #declare Sturm = 0; #end
global_settings { assumed_gamma 1.0 }

#macro Solver() #if (Sturm) sturm #end #end
#macro Precise(G) max_gradient G * (Sturm ? 2 : 1) #if (Sturm) accuracy 1e-6 #end #end
#declare Far = <1e4, 0, 1e4>;
#declare Lit = finish { ambient 0.15 diffuse 0.8 phong 0.4 }
#declare Dome = lathe {
    bezier_spline 8,
    <0, -1>, <0.7, -1>, <1, -0.5>, <1, 0>,
    <1, 0>, <1, 0.6>, <0.6, 1>, <0, 1>
    Solver()
    pigment { color rgb <0.9, 0.3, 0.2> } finish { Lit }
}
background { color rgb <0.2, 0.25, 0.3> }

#switch (Case)
#case (1)
    camera { location <0, 5, 0> look_at 0 angle 30 }
    light_source { <-3, 9, -4> color rgb 1 }
    object { Dome }
    plane { y, -1 pigment { checker color rgb 0.8 color rgb 0.6 } }
#break
#case (2)
    camera { location Far + <0, 1.4e4, 0> look_at Far angle 0.01 }
    light_source { Far + <-30, 100, -60> color rgb 1 }
    object { Dome rotate 20*x translate Far }
#break
#case (3)
    camera { location <0, 5, 0> look_at 0 angle 30 }
    light_source { <-3, 9, -4> color rgb 1 }
    sor {
        6, <0.3, -1.4>, <0.6, -1>, <0.9, -0.3>, <0.4, 0.4>, <0, 0.8>, <0.2, 1.2>
        Solver()
        pigment { color rgb <0.3, 0.4, 0.9> } finish { Lit }
    }
#break
#case (4)
    camera { location <0, 3, -5> look_at <0, 0, 0> angle 45 }
    light_source { <-4, 9, -5> color rgb 1 }
    isosurface {
        function { pow(x, 8) + pow(y, 8) + pow(z, 8) - 0.3 }
        contained_by { box { -1, 1 } }
        Precise(14)
        pigment { color rgb <0.2, 0.7, 0.3> } finish { Lit }
        translate <-1.1, 0, 0>
    }
    isosurface {
        function { sqrt(x*x + y*y + z*z) - 0.8 + 0.03 * sin(40 * x) * sin(40 * y) }
        contained_by { sphere { 0, 1 } }
        Precise(3)
        pigment { color rgb <0.9, 0.3, 0.2> } finish { Lit }
        translate <1.1, 0, 0>
    }
#break
#case (5)
    camera { location <0, 0.35, -4> look_at <0, 0.2, 0> angle 40 }
    light_source { <-4, 9, -5> color rgb 1 }
    isosurface {
        function { abs(sqrt(x*x + y*y + z*z) - 0.8) - 0.01 }
        contained_by { box { <-1, -1, -1>, <1, 0.3, 1> } }
        Precise(1.1)
        pigment { color rgb <0.3, 0.4, 0.9> } finish { Lit }
    }
#break
#end

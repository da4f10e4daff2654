// Stability: the numerically hard cases of the polynomial shapes, one per
// value of Case (tests/stability/run_speckles.sh renders each with and
// without Sturm=1 and counts NaN pixels and isolated speckles against the
// Sturm render):
//   1 a thin torus (minor/major 1/100) nearly edge-on, 300 units away
//   2 a torus 1.4e4 units from the camera, at x = z = 1e4
//   3 a quartic (the torus of shapesq.inc's Torus_40_12) at the same place
//   4 a blob whose threshold (0.95) is close to its components' strength 1
//   5 a poly of order 6 (Twin_Glob) 1e4 units away
//
//     frameray polynomial_cases.pov +W160 +H120 Declare=Case=2 Declare=Sturm=1
#version 3.7;
#ifndef (Case) #declare Case = 1; #end
#ifndef (Sturm) #declare Sturm = 0; #end
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
#include "shapesq.inc"

#macro Solver() #if (Sturm) sturm #end #end
#declare Far = <1e4, 0, 1e4>;
#declare Lit = finish { ambient 0.15 diffuse 0.8 phong 0.4 }

#switch (Case)
#case (1)
    camera { location <0, 0, -300> look_at 0 angle 0.45 }
    light_source { <-100, 300, -300> color rgb 1 }
    torus { 1, 0.01 Solver() rotate x * 88.5 rotate z * 10 pigment { color rgb <0.9, 0.5, 0.2> } finish { Lit } }
    background { color rgb <0.2, 0.25, 0.3> }
#break
#case (2)
    camera { location <0, 1.5, 0> look_at Far angle 0.012 }
    light_source { Far + <-30, 100, -60> color rgb 1 }
    torus { 1, 0.35 Solver() rotate x * -45 translate Far pigment { color rgb <0.9, 0.5, 0.2> } finish { Lit } }
    background { color rgb <0.2, 0.25, 0.3> }
#break
#case (3)
    camera { location <0, 1.5, 0> look_at Far angle 0.012 }
    light_source { Far + <-30, 100, -60> color rgb 1 }
    object { Torus_40_12 Solver() scale 0.13 rotate x * -45 translate Far
        pigment { color rgb <0.3, 0.8, 0.35> } finish { Lit } }
    background { color rgb <0.2, 0.25, 0.3> }
#break
#case (4)
    camera { location <0, 2, -4> look_at 0 angle 40 }
    light_source { <-5, 10, -6> color rgb 1 }
    blob {
        threshold 0.95
        sphere { <-0.5, 0, 0>, 1.6, 1 }
        sphere { <0.5, 0.2, 0>, 1.6, 1 }
        cylinder { <-1, -0.5, 0.5>, <1, -0.5, 0.5>, 1.4, 1 }
        Solver()
        pigment { color rgb <0.3, 0.5, 0.95> } finish { Lit }
    }
    background { color rgb <0.2, 0.25, 0.3> }
#break
#case (5)
    camera { location <0, 1.5, 0> look_at Far angle 0.02 }
    light_source { Far + <-30, 100, -60> color rgb 1 }
    object { Twin_Glob Solver() clipped_by { box { -2, 2 } } rotate <-30, 20, 0> translate Far
        pigment { color rgb <0.9, 0.85, 0.3> } finish { Lit } }
    background { color rgb <0.2, 0.25, 0.3> }
#break
#end

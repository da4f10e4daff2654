// Accuracy study: radiosity. A closed room lit by one lamp through the
// light bouncing off its walls: a red box and a blue sphere bleed colour
// onto the walls and floor; most of the image is indirect light.
// study-knobs: rad_count rad_error_bound rad_pretrace_end rad_recursion rad_nearest
// study-baseline: -A Declare=RadCount=35 Declare=RadErrorBound=1.8 Declare=RadPretraceEnd=0.04 Declare=RadRecursion=2 Declare=RadNearest=5
// study-reference: -A Declare=RadCount=400 Declare=RadErrorBound=0.2 Declare=RadPretraceEnd=0.01 Declare=RadRecursion=3 Declare=RadNearest=10
#version 3.7;
#ifndef (RadCount) #declare RadCount = 35; #end
#ifndef (RadErrorBound) #declare RadErrorBound = 1.8; #end
#ifndef (RadPretraceEnd) #declare RadPretraceEnd = 0.04; #end
#ifndef (RadRecursion) #declare RadRecursion = 2; #end
#ifndef (RadNearest) #declare RadNearest = 5; #end
global_settings {
    assumed_gamma 1
    radiosity {
        count RadCount error_bound RadErrorBound pretrace_start 0.08 pretrace_end RadPretraceEnd
        recursion_limit RadRecursion nearest_count RadNearest
    }
}
camera { location <0, 2, -5.5> look_at <0, 1.6, 0> angle 62 }
light_source { <-2.5, 3.6, -2> rgb 1.3 }
#declare Matte = finish { ambient 0 diffuse 0.75 }
box { <-4, 0, -6>, <4, 4, 4> inverse texture { pigment { rgb <0.85, 0.82, 0.75> } finish { Matte } } }
box { <-1, 0, -1>, <1, 2, 1> rotate y * 30 translate <1.4, 0, 1.5>
      texture { pigment { rgb <0.9, 0.15, 0.1> } finish { Matte } } }
sphere { <-1.8, 0.9, 0.2>, 0.9 texture { pigment { rgb <0.15, 0.35, 0.9> } finish { Matte } } }

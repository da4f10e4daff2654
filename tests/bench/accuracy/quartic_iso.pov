// Accuracy study: root finding. Thin tori seen edge-on (quartic roots that
// the closed-form solver loses at grazing angles unless `sturm` is on) and
// two isosurfaces whose surface position is found to within IsoAccuracy.
// study-knobs: sturm iso_accuracy aa_threshold quality
// study-baseline: +A0.3 +R3 -J Declare=Sturm=0 Declare=IsoAccuracy=0.001
// study-reference: +A0.02 +R4 -J Declare=Sturm=1 Declare=IsoAccuracy=0.000001
#version 3.7;
#ifndef (Sturm) #declare Sturm = 0; #end
#ifndef (IsoAccuracy) #declare IsoAccuracy = 0.001; #end
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -7> look_at <0, 0.9, 0> angle 48 }
light_source { <-4, 8, -6> rgb 1 }
light_source { <5, 3, -4> rgb 0.3 }
background { rgb <0.5, 0.6, 0.8> }
plane { y, -0.5 pigment { rgb 0.8 } }
#for (I, 0, 4)
    torus {
        1.2, 0.04 + I * 0.01
        sturm Sturm
        rotate x * (84 + I * 1.5) translate <-2.3 + I * 0.15, 1.6, 1 + I * 0.4>
        pigment { rgb <0.9, 0.5 + I * 0.1, 0.2> } finish { phong 0.7 }
    }
#end
isosurface {  // tanglecube
    function { pow(x, 4) - 5 * x * x + pow(y, 4) - 5 * y * y + pow(z, 4) - 5 * z * z + 11.8 }
    contained_by { box { -2.4, 2.4 } }
    accuracy IsoAccuracy
    max_gradient 36
    scale 0.35 rotate <20, 30, 0> translate <1.6, 1.0, 0.5>
    pigment { rgb <0.3, 0.7, 0.9> } finish { phong 0.6 }
}
isosurface {  // a bumpy sphere
    function { sqrt(x * x + y * y + z * z) - 0.8 - 0.06 * sin(10 * x) * sin(10 * y) * sin(10 * z) }
    contained_by { sphere { 0, 1 } }
    accuracy IsoAccuracy
    max_gradient 2.2
    translate <0, 0.4, -1.2>
    pigment { rgb <0.5, 0.9, 0.4> } finish { phong 0.5 }
}

// frameray demo animation: a little orrery. Three planets circle a sun on
// a chequer-free stone floor, each spinning on a tilted plinth; one turn of
// the clock is one orbit, so the cyclic sequence loops seamlessly.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

#declare Turn = clock * 360;

camera {
    location <0, 5.5, -9>
    look_at <0, 0.6, 0>
    angle 55
    right x * image_width / image_height
}

light_source { <-6, 10, -5> color rgb <1.0, 0.96, 0.9> }
light_source { <7, 4, -8> color rgb <0.25, 0.3, 0.4> }

background { color rgb <0.05, 0.06, 0.1> }

plane { y, 0 pigment { color rgb <0.55, 0.5, 0.45> } finish { ambient 0.05 diffuse 0.8 } }

// The sun sits on a pedestal.
box { <-0.6, 0, -0.6>, <0.6, 0.4, 0.6> pigment { color Gray40 } }
sphere { <0, 1.3, 0>, 0.9
    pigment { color rgb <1.0, 0.75, 0.25> }
    finish { ambient 0.35 diffuse 0.6 phong 0.4 phong_size 30 }
}

#macro Planet(Radius, Size, Speed, Phase, Colour)
    sphere { <Radius, Size + 0.1, 0>, Size
        pigment { color Colour }
        finish { phong 0.8 phong_size 60 }
        rotate y * (Turn * Speed + Phase)
    }
    box { <-0.15, 0, -0.15>, <0.15, 0.1, 0.15>
        pigment { color Gray20 }
        rotate y * 45
        translate x * Radius
        rotate y * (Turn * Speed + Phase)
    }
#end

Planet(2.2, 0.30, 3, 0, rgb <0.3, 0.55, 1.0>)
Planet(3.3, 0.45, 2, 120, rgb <0.85, 0.3, 0.25>)
Planet(4.6, 0.38, 1, 250, rgb <0.35, 0.8, 0.4>)

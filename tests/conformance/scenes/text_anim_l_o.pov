// The text labels of POV-Ray's example animation animations/l_o/l_o.pov,
// kept alone with its camera and light (and their unions' moves).
#version 3.7;
global_settings { assumed_gamma 1.5 }
#include "colors.inc"

camera {
    location <0, 0, -10>
    right     x*image_width/image_height
    angle 55
    look_at 0
}

light_source { <-20, 30, -25> rgb 1 }

#declare L = clock * 3;
#declare Font="cyrvetic.ttf"

text{ ttf Font
    concat("lambda=",str(L,1,2)),0.1,0
    scale <1.25, 1.25, 2>
    translate <-3, 1, -1>
    pigment { Cyan }
    translate y*1.25
}

#declare O = clock;
text{ ttf Font
    concat("omega=",str(O,1,2)),0.1,0
    scale <1.25, 1.25, 2>
    translate <-3, 1, -1>
    pigment { Cyan }
    translate -y*1.65
}

// The text labels of POV-Ray's example animation animations/vect1/vect1.pov
// (by Chris Young), kept alone with its camera and light.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#declare Font="cyrvetic.ttf"
#declare Clock360 = 360*clock;
#declare ClockRot = Clock360*z;
#declare Attach_Point=vrotate(x*3,ClockRot);
#declare Fixed_Point =x*8;
#declare Long_Length=vlength(Attach_Point - Fixed_Point);

text{ttf Font concat("Angle=",str(Clock360,1,1)),0.1,0 scale 2 pigment{color rgb<1,0.1,0>} translate <-3.5,3.5,0>}
text{ttf Font concat("Length=",str(Long_Length,1,1)),0.1,0 scale 2 pigment{color rgb<0.3,0.9,0>} translate <-3.5,-5,0>}

camera {
   location  <0, 0, -120>
  right     x*image_width/image_height
   direction <0, 0.5,  10>
   look_at   <0, 0,   0>
}

light_source { <5000, 10000, -20000> color White}

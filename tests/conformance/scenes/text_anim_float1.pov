// The text labels of POV-Ray's example animation animations/float1/float1.pov,
// kept alone with its camera and light (and their colours and places).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare A = clock;
#declare B = sin(radians(A*360));
#declare C = cos(radians(A*360));
#declare D = min(B,C);
#declare E = max(B,C);
#include "colors.inc"
#declare TFudge=<-6.25,0,0.2>;
#declare Font="cyrvetic.ttf"

camera {
   location  <0, 0, -120>
   right     x*image_width/image_height
   direction <0, 0,  12>
   look_at   <0, 0,   0>
}

light_source { <5000, 10000, -20000> color White}

text{ttf Font concat("A=clock=",str(A,0,2)),0.1,0 translate TFudge pigment{color rgb<1,0.1,0>} translate 4*y}
text{ttf Font concat("B=sin(radians(A*360)=",str(B,0,2)),0.1,0 translate TFudge pigment{color rgb<0.3,0.9,0>} translate 2*y}
text{ttf Font concat("C=cos(radians(A*360)=",str(C,0,2)),0.1,0 translate TFudge pigment{Blue}}
text{ttf Font concat("D=min(B,C)=",str(D,0,2)),0.1,0 translate TFudge pigment{Cyan} translate -2*y}
text{ttf Font concat("E=max(B,C)=",str(E,0,2)),0.1,0 translate TFudge pigment{Magenta} translate -4*y}

// The text labels of POV-Ray's example animation animations/float2/float2.pov,
// kept alone with its camera and light (and their colours and places).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare F = clock*10-5;
#declare G = floor(F);
#declare H = ceil(F);
#declare I = int(F);
#declare J = abs(F);
#include "colors.inc"
#declare TFudge=<-6,0,0.2>;
#declare Font="cyrvetic.ttf"

camera {
   location  <0, 0, -120>
   direction <0, 0,  12>
   look_at   <0, 0,   0>
}

light_source { <5000, 10000, -20000> color White}

text{ttf Font concat("F=clock*10-5=",str(F,0,2)),0.1,0 translate TFudge pigment{Red} translate 4*y}
text{ttf Font concat("G=floor(F)=",str(G,0,2)),0.1,0 translate TFudge pigment{Green} translate 2*y}
text{ttf Font concat("H=ceil(F)=",str(H,0,2)),0.1,0 translate TFudge pigment{Blue} translate 0*y}
text{ttf Font concat("I=int(F)",str(I,0,2)),0.1,0 translate TFudge pigment{Cyan} translate -2*y}
text{ttf Font concat("J=abs(F)=",str(J,0,2)),0.1,0 translate TFudge pigment{Magenta} translate -4*y}

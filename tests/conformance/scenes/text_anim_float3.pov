// The text labels of POV-Ray's example animation animations/float3/float3.pov,
// kept alone with its camera and light (and their colours and places).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare K = clock*12-6;
#declare L = mod(K,2);
#declare M = div(K,2);
#declare N = mod(K,3);
#declare Oh = div(K,3);
#include "colors.inc"
#declare TFudge=<-6,0,0.2>;
#declare Font="cyrvetic.ttf"

camera {
   location  <0, 0, -120>
   direction <0, 0,  12>
   look_at   <0, 0,   0>
}

light_source { <5000, 10000, -20000> color White}

text{ttf Font concat("K=clock*12-6=",str(K,0,2)),0.1,0 translate TFudge pigment{Red} translate 4*y}
text{ttf Font concat("L=mod(K,2)=",str(L,0,2)),0.1,0 translate TFudge pigment{Green} translate 2*y}
text{ttf Font concat("M=div(K,2)=",str(M,0,2)),0.1,0 translate TFudge pigment{Blue} translate 0*y}
text{ttf Font concat("N=mod(K,3)=",str(N,0,2)),0.1,0 translate TFudge pigment{Cyan} translate -2*y}
text{ttf Font concat("O=div(K,3)=",str(Oh,0,2)),0.1,0 translate TFudge pigment{Magenta} translate -4*y}

// The text labels of POV-Ray's example animation animations/float4/float4.pov,
// kept alone with its camera and light (and the union's final move).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#declare Font="cyrvetic.ttf"

camera {
   location  <0, 0, -140>
   direction <0, 0,  11>
   look_at   <0, 0,   0>
}

light_source { <5000, 10000, -20000> color White}

#declare A=4;
#declare B=3*clock;
#declare C=sqrt(pow(A,2)+pow(B,2));
#declare Angle_b=atan2(B,A);
#declare b_Degrees=degrees(Angle_b);

union {
  text{ttf Font "A=4",0.1,0 translate <1,-5,0> pigment{color rgb<1,0.1,0>}}
  text{ttf Font concat("B=",str(B,1,2)),0.1,0 translate <4.25,-1.25,0> pigment{color rgb<0.2,0.1,0.5,>}}
  text{ttf Font "C=sqrt(pow(A,2)",0.1,0  translate <-9,2,0> pigment{color rgb<0.1,0.5,0>}}
  text{ttf Font "+pow(B,2))",0.1,0  translate <-7,1,0> pigment{color rgb<0.1,0.5,0>}}
  text{ttf Font concat("C=",str(C,1,2)),0.1,0 pigment{color rgb<1,0.6,0>}
       translate (C+0.3)*y
       rotate z*b_Degrees
      }
  text{ttf Font concat("b=atan2(B,C)=",str(Angle_b,1,2)),0.1,0 translate <-9,-1,0> pigment{Magenta*.7}}
  text{ttf Font concat("degrees(b)=",str(b_Degrees,1,2)),0.1,0 translate <-8.5,-2,0> pigment{Magenta*.7}}

  translate x-y
}

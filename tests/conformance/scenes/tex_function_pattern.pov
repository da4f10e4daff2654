// A function { } as a pigment pattern (values wrap above one, negatives
// through the ramp wave) and as a normal pattern with a bump size.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0,0,-5> look_at 0 right x*4 up y*3 }
light_source { <-5,10,-10> color rgb 1 }
#declare F = function(a,b) { a*a - b }
plane { z, 0
  pigment { function { F(x,y)*0.8 + 0.1*sin(4*x) } color_map { [0 rgb <1,0,0>] [0.3 rgb <0,1,0>] [0.7 rgb <0,0,1>] [1 rgb 1] } }
  finish { ambient 0.3 diffuse 0.7 }
  normal { function { sin(x*6)*cos(y*6) } 0.4 scale 0.5 }
}

// Fractal patterns as normals, with the bump size after a comma: magnet 1
// mandel, mandel with exponent 3 and colouring types, magnet 2 julia.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 angle 60 }
light_source { <-5,10,-10> color rgb 1 }
box { <-2.4,-1.6,0>, <-0.05,1.6,1> pigment { rgb 0.9 } normal { magnet 1 mandel 20, 0.5 scale 0.8 translate <-0.7,0,0> } }
box { <0.05,0.05,0>, <2.4,1.6,1> pigment { rgb <0.9,0.8,0.6> } normal { mandel 20, 0.5 exponent 3 interior 1, 2 exterior 2, 1 scale 0.6 translate <1.2,0.8,0> } }
box { <0.05,-1.6,0>, <2.4,-0.05,1> pigment { rgb <0.6,0.8,0.9> } normal { magnet 2 julia <0.6,0.9>, 25, 0.8 scale 0.5 translate <1.2,-0.8,0> } }

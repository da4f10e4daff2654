// agate with the classic turbulence keyword: povray displaces the point as
// warp { turbulence } does, and agate's own noise uses the octaves, omega
// and lambda (stones2.inc T_Stone26); in a texture_map and a normal too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-30> look_at 0 right 10*x up 10*y }
light_source { <-30, 40, -60> rgb 1 }
#macro S(X,Y) translate <X*2.5-3.75,Y*2.5-3.75,0> #end
#declare CM = color_map { [0 rgb 0][0.3 rgb <1,0.5,0>][0.6 rgb <0,0.5,1>][1 rgb 1] }
sphere { 0, 1 pigment { agate color_map{CM} } S(0,0) }
sphere { 0, 1 pigment { agate color_map{CM} turbulence 0.05 } S(1,0) }
sphere { 0, 1 pigment { agate color_map{CM} octaves 3 } S(2,0) }
sphere { 0, 1 pigment { agate color_map{CM} omega 0.7 } S(3,0) }
sphere { 0, 1 pigment { agate color_map{CM} lambda 2.5 } S(0,1) }
sphere { 0, 1 pigment { agate color_map{CM} agate_turb 0.5 } S(1,1) }
sphere { 0, 1 pigment { agate color_map{CM} frequency 3 } S(2,1) }
sphere { 0, 1 pigment { agate color_map{CM} turbulence <0.05,0.05,0.05> octaves 6 omega 0.7 lambda 2 } S(3,1) }
sphere { 0, 1 pigment { agate color_map{CM} octaves 6 omega 0.7 lambda 2 } S(0,2) }
sphere { 0, 1 pigment { agate color_map{CM} turbulence 0.5 } S(1,2) }
sphere { 0, 1 pigment { agate color_map{CM} warp { turbulence 0.5 } } S(2,2) }
sphere { 0, 1 pigment { marble color_map{CM} turbulence 0.5 octaves 3 } S(3,2) }
sphere { 0, 1 texture { agate turbulence 0.5 texture_map { [0.4 pigment { granite scale 0.3 }] [0.6 pigment { rgb <1,0.5,0> }] } } S(0,3) }
sphere { 0, 1 normal { agate 1 turbulence 0.4 scale 0.5 } pigment { rgb 1 } S(1,3) }

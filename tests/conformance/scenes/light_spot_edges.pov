// Spotlight cones at their edge cases, as povray 3.7 lights them: radius 0
// fades all the way from the axis to the falloff cone; a falloff inside
// the radius cone acts as the radius (a hard edge); radius and falloff 0
// light nothing off the axis; and the usual radius < falloff between them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -20> look_at 0 right 16 * x up 12 * y }
plane { -z, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#macro Spot(C, R, F, T)
  light_source { <C.x, C.y, -12> rgb 1 spotlight point_at <C.x, C.y, 0> radius R falloff F tightness T }
#end
Spot(<-4, 3, 0>, 0, 11, 0)
Spot(<4, 3, 0>, 11, 5, 0)
Spot(<-4, -3, 0>, 0, 0, 0)
Spot(<4, -3, 0>, 5, 12, 10)

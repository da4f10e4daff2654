// #default: finish, pigment and texture blocks; objects without a texture,
// objects with only a pigment or finish, CSG children, declared textures
// and finishes all start from the default in force.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,2,-6> look_at 0 angle 50 }
light_source { <-5,10,-10> color rgb 1 }
sphere { <-2.2,0,0>, 0.8 }
#default { finish { ambient 0.3 diffuse 0.5 phong 0.8 } }
#default { pigment { rgb <0.9,0.6,0.2> } }
sphere { <-0.5,0,0>, 0.8 }
sphere { <1.1,0,0>, 0.8 pigment { rgb <0.2,0.4,1> } }
union { sphere { <2.5,0.5,0>, 0.5 } box { <2,-1,-0.5>, <3,0,0.5> pigment { checker rgb 1 rgb 0 scale 0.25 } } }
#default { texture { pigment { rgb <0.3,0.9,0.3> } finish { ambient 0.1 diffuse 0.9 } } }
#declare T = texture { pigment { rgb <1,0,1> } }
plane { y, -1 }
cylinder { <0,-1,2>, <0,1,2>, 0.4 texture { T } }
#declare F = finish { phong 1 }
box { <-3,-1,1.5>, <-2,0,2.5> finish { F } }

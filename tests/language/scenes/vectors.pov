// Language test: vector literals and expressions, promotion of floats and
// short vectors, dot items, built-in vector identifiers and the vector
// functions vaxis_rotate, vcross, vrotate, vnormalize and vturbulence.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "vectors.out" write

// Rounds away the last bits of trigonometry so results print exactly.
#macro Round(A) (floor((A)*1e9+0.5)/1e9) #end
#macro RV(V) <Round(V.x), Round(V.y), Round(V.z)> #end

// Literals of 2 to 5 components and how #write prints them
#write (Out, "literal 3d ", <1.0, 3.2, -5.4578>, "\n")
#write (Out, "literal 2d ", <1,2>, " 4d ", <1,2,3,4>, " 5d ", <1,2,3,4,5>, "\n")
#write (Out, "literal expressions ", <1+1, 2*3, -1/4>, "\n")
#write (Out, "literal without comma means 3.2-5 ", <1, 3.2 -5, 7>, "\n")

// Built-in vector identifiers (a #write item must not start with t)
#write (Out, "builtins x y z ", x, " ", y, " ", z, "\n")
#write (Out, "builtins u v ", u, " ", v, " t ", 0+t, "\n")
#write (Out, "builtins 5*x ", 5*x, " x+y+z ", x+y+z, " -y ", -y, "\n")

// Component-wise arithmetic
#write (Out, "add ", <1,2,3> + <4,5,6>, "\n")
#write (Out, "sub ", <1,2,3> - <4,5,6>, "\n")
#write (Out, "mul ", <1,2,3> * <4,5,6>, "\n")
#write (Out, "div ", <1,2,3> / <4,5,6>, "\n")
#write (Out, "precedence ", <1,2,3> + <1,1,1> * 2, " ", (<1,2,3> + <1,1,1>) * 2, "\n")
#write (Out, "negate ", -<1,-2,3>, " ", - -<1,2,3>, "\n")
#write (Out, "not ", !<0,1,0>, "\n")
#write (Out, "vector minus float ", <1,2,3>-4, "\n")
#write (Out, "float over vector ", 2/<1,2,4>, "\n")
#write (Out, "float times vector ", 3*<1,2,3>, " ", <1,2,3>*0.5, "\n")

// Promotion: a float becomes all components, a short vector gets zeros
#write (Out, "promote float+vector ", <1,2,3> + 1, "\n")
#write (Out, "promote 2d+3d ", <1,2> + <1,2,3>, "\n")
#write (Out, "promote 4d+2d ", <1,2,3,4> + <7,6>, "\n")
#write (Out, "promote 5d*float ", <1,2,3,4,5> * 2, "\n")
#write (Out, "promote 4d+x ", <1,1,1,1> + x, " 4d+t ", <1,1,1,1> + t, "\n")
#write (Out, "promote vstr 4 of <7,6> ", vstr(4, <7,6>, ",", 0, 1), "\n")
#write (Out, "promote vstr 4 of 9 ", vstr(4, 9, ",", 0, 1), "\n")
#declare Scale = 5;
#declare Moved = <0,0,0> + Scale;
#write (Out, "promote declared float ", Moved, "\n")

// Relational and conditional operators on vectors
#write (Out, "vector equality ", (<1,2,3> = <3,2,1>), "\n")
#write (Out, "vector less ", (<1,2,3> < 2), " ", (<1,2,3> < <3,2,1>), "\n")
#write (Out, "vector conditional ", (1 ? <1,2,3> : <5,6,7>), " ", (2 < 1 ? <1,2,3> : <5,6,7>), "\n")

// Dot items
#declare Spot = <1.5, -2, 3.25>;
#declare Flat = <7, 8>;
#declare Quad = <1, 2, 3, 4>;
#declare Five = <0.1, 0.2, 0.3, 0.4, 0.5>;
#write (Out, "dot x y z ", Spot.x, " ", Spot.y, " ", Spot.z, "\n")
#write (Out, "dot u v ", Flat.u, " ", Flat.v, " x y of 2d ", Flat.x, " ", Flat.y, "\n")
#write (Out, "dot t ", Quad.t, " ", Quad.x, "\n")
#write (Out, "dot red green blue ", Spot.red, " ", Spot.green, " ", Spot.blue, "\n")
// A 5-component identifier counts as a colour: a #write item must not start with one.
#write (Out, "dot filter transmit ", (Five.filter), " ", (Five.transmit), " ", 0+Five.x, "\n")
#write (Out, "dot gray ", Spot.gray, " ", <1,1,1>.gray, " ", <1,0,0>.gray, " ", <0,1,0>.gray, " ", <0,0,1>.gray, "\n")
#write (Out, "dot on literal ", <4,5,6>.y, "\n")
#write (Out, "dot on parentheses ", (<1,2,3>*2).z, "\n")
#write (Out, "dot on function ", vcross(x,y).z, "\n")
#write (Out, "dot in expression ", Spot.x*2 + Spot.y, "\n")

// Vector functions
#write (Out, "vcross x,y ", vcross(x, y), " y,x ", vcross(y, x), "\n")
#write (Out, "vcross ", vcross(<1,2,3>, <4,5,6>), "\n")
#write (Out, "vcross parallel ", vcross(<1,2,3>, <2,4,6>), "\n")
#write (Out, "vnormalize ", vnormalize(<3,0,4>), " ", vnormalize(<0,-2,0>), "\n")
#write (Out, "vnormalize length ", vlength(vnormalize(<1,2,3>)), "\n")
#write (Out, "vnormalize 1,1,1 ", vstr(3, vnormalize(<1,1,1>), ",", 0, 9), "\n")
#write (Out, "vrotate x by 90z ", RV(vrotate(x, <0,0,90>)), "\n")
#write (Out, "vrotate y by 90x ", RV(vrotate(y, <90,0,0>)), "\n")
#write (Out, "vrotate x by 90y ", RV(vrotate(x, <0,90,0>)), "\n")
#write (Out, "vrotate order x,y,z ", RV(vrotate(<1,2,3>, <90,90,0>)), " ", RV(vrotate(<1,2,3>, <0,90,90>)), "\n")
#write (Out, "vrotate angles ", vstr(3, vrotate(<1,2,3>, <30,45,60>), ",", 0, 9), "\n")
#write (Out, "vaxis_rotate x about z 90 ", RV(vaxis_rotate(x, z, 90)), "\n")
#write (Out, "vaxis_rotate about y ", RV(vaxis_rotate(<1,2,3>, y, 90)), "\n")
#write (Out, "vaxis_rotate unnormalised axis ", RV(vaxis_rotate(<1,0,0>, <0,0,5>, 180)), "\n")
#write (Out, "vaxis_rotate diagonal ", vstr(3, vaxis_rotate(<1,0,0>, <1,1,1>, 120), ",", 0, 9), "\n")
#write (Out, "vaxis_rotate 37 ", vstr(3, vaxis_rotate(<1,2,3>, <-1,0.5,2>, 37), ",", 0, 9), "\n")
#write (Out, "vector functions nested ", RV(vnormalize(vcross(vrotate(x, <0,0,45>), z))), "\n")
// vturbulence(Lambda, Omega, Octaves, P): povray's turbulence vector.
#for (I, 0, 4)
  #write (Out, "vturbulence ", I, " ", vstr(3, vturbulence(2 + I*0.1, 0.5, 6 - I, <0.3 + I, 0.2*I, 0.1 - I*3.7>), ",", 0, 9), "\n")
#end
#write (Out, "vturbulence far ", vstr(3, vturbulence(1.5, 0.7, 3, <1e3, -20.5, 7>), ",", 0, 9), "\n")
#fclose Out

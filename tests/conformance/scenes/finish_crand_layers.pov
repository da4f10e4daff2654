// crand in layered textures: a layer's darkening (crand times a random
// number times its pigment) carries on to every layer below it, as in
// povray (incdemo/stones/stones1.pov's granite layers). Left: a clear
// white crand layer over a crand layer; middle: three half-transparent
// crand layers; right: a crand layer over a plain one. Compared by local
// means (--blur): povray's numbers change from render to render.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 angle 40 }
light_source { <0, 0, -100> rgb 1 }
#declare Clear = texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0.8 crand 0.3 } }
#declare Half = texture { pigment { rgbt <1, 0.9, 0.7, 0.5> } finish { ambient 0 diffuse 0.8 crand 0.2 } }
#declare Base = texture { pigment { rgb <0.8, 0.8, 0.6> } finish { ambient 0 diffuse 0.8 crand 0.3 } }
#declare Plain = texture { pigment { rgb <0.6, 0.8, 0.8> } finish { ambient 0.1 diffuse 0.7 } }
box { <-4.5, -3, 0>, <-1.6, 3, 1> texture { Base } texture { Clear } }
box { <-1.4, -3, 0>, <1.4, 3, 1> texture { Base } texture { Half } texture { Half } }
box { <1.6, -3, 0>, <4.5, 3, 1> texture { Plain } texture { Half } }

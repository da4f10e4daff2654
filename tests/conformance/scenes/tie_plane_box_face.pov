// A see-through box whose bottom face lies in a plane: povray (bounding on,
// which a scene of three or more objects and lights gets) tests unbounded
// objects first and a bounded surface at the same distance must be nearer
// to win, so the plane shows through the box's top face only, whichever is
// declared first (textures/pigments/filtfun.pov's boxes on the floor).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -4.5> angle 65 right x*4/3 look_at <0, 0.4, 0> }
light_source { <20, 12, -40> rgb 1 }
box { <-1, -1, -1>, <1, 1, 1> rotate 45*y translate <-1.2, 1, 1>
      pigment { rgbt <0, 0, 1, 0.5> } finish { ambient 1 diffuse 0 } }
box { <-1, 0, -1>, <1, 0.5, 1> translate <1.5, 0, 0>
      pigment { rgbf <0, 1, 0, 0.6> } finish { ambient 0.6 diffuse 0.4 } }
plane { y, 0 pigment { checker rgb <1, 0, 0> rgb <1, 1, 0> } finish { ambient 0.3 diffuse 0.7 } }

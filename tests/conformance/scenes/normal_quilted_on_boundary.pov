// A plane lying exactly on the quilted pattern's cell boundary (y = 0 is a
// whole number in pattern space): which cell each hit point falls in
// depends on the last bit of the primary ray, so the normal's tilt (large at
// bump size 1) matches povray's only when the camera vectors and the ray
// directions are computed with povray's own arithmetic (angle through
// pi/360, unit vectors by reciprocal length, rows counted from the bottom).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -6> look_at <0, 0, 0> angle 50 }
light_source { <10, 20, -10> color rgb 1 }
light_source { <-20, 5, 10> color rgb <0.5, 0.4, 0.3> }
plane {
    y, 0
    texture {
        pigment { rgb <0.2, 0.3, 0.9> }
        normal { quilted 1.0 control0 1 control1 1 scale <0.45, 1, 0.45> }
        finish { phong 0.5 }
    }
}

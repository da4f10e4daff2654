// Conformance: flat and smooth triangles — a faceted pyramid, a smooth
// shaded patch (normals from a sphere), a tilted triangle with a phong
// highlight, and triangles under a transform.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.5, -7> look_at <0, 0.9, 0> angle 55 }

light_source { <-6, 9, -8> color rgb <1, 1, 1> }
light_source { <6, 4, -3> color rgb <0.3, 0.3, 0.3> }

plane { y, 0 pigment { color rgb <0.7, 0.7, 0.7> } }

// A four-sided pyramid.
#declare Apex = <-2.2, 1.8, 0>;
union {
    triangle { <-3.2, 0, -1>, <-1.2, 0, -1>, Apex }
    triangle { <-1.2, 0, -1>, <-1.2, 0, 1>, Apex }
    triangle { <-1.2, 0, 1>, <-3.2, 0, 1>, Apex }
    triangle { <-3.2, 0, 1>, <-3.2, 0, -1>, Apex }
    pigment { color rgb <0.9, 0.5, 0.2> }
}

// Two smooth triangles forming a bulging square, normals of a sphere.
#declare C = <0.3, 1, 0.5>;
#declare P1 = <-0.7, 0.2, -0.5>;
#declare P2 = <1.3, 0.2, -0.5>;
#declare P3 = <1.3, 2.0, -0.5>;
#declare P4 = <-0.7, 2.0, -0.5>;
#declare Bulge = <0, 0, -1.6>;
union {
    smooth_triangle { P1, vnormalize(P1 - C + Bulge), P2, vnormalize(P2 - C + Bulge), P3, vnormalize(P3 - C + Bulge) }
    smooth_triangle { P1, vnormalize(P1 - C + Bulge), P3, vnormalize(P3 - C + Bulge), P4, vnormalize(P4 - C + Bulge) }
    pigment { color rgb <0.3, 0.6, 0.95> }
    finish { phong 0.7 phong_size 30 }
}

// A single tilted triangle with a highlight.
triangle { <2, 0.3, -1.5>, <3.6, 0.6, -0.5>, <2.6, 2.4, 0.6> pigment { color rgb <0.4, 0.85, 0.4> } finish { specular 0.6 } }

// A triangle scaled and rotated.
triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> scale <1.5, 0.8, 1> rotate <0, -30, 20> translate <-0.8, 0.1, -2.4>
    pigment { color rgb <0.9, 0.85, 0.3> } }

// Surfaces closer together than povray's minimum hit distances
// (scene/hit_tolerance.h): povray drops a crossing nearer than 1e-4 to a
// ray's origin, 1e-3 on shadow rays, 1e-2 on blobs.
//  - left: a glass bowl (sphere shell) holding a red liquid whose radius is
//    1e-8 more than the bowl's inner radius (advanced/grenadine's juice);
//  - middle: a bubble, a shell 1e-6 thick;
//  - right: a translucent slab 5e-4 above the floor: the floor's shadow
//    rays do not see its underside (1e-3), only its top;
//  - front: two blob spheres whose surfaces are 1e-3 apart, seen along the
//    line through their centres.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2.5, -7> look_at <0, 0.6, 0> angle 45 }
light_source { <-3, 8, -6> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.3, 0.4, 0.8>] [1 rgb 1] } } }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 scale 0.5 } finish { diffuse 0.8 } }

#declare Ri = 0.75;
union {
    difference {
        sphere { 0, 0.85 }
        sphere { 0, Ri }
        material { texture { pigment { rgbf <1, 1, 1, 0.9> } finish { specular 0.5 reflection 0.1 } }
                   interior { ior 1.5 } }
    }
    sphere { 0, Ri + 1e-8
        material { texture { pigment { rgbf <0.9, 0.2, 0.2, 0.9> } finish { reflection 0.2 } }
                   interior { ior 1.2 } } }
    translate <-2, 0.9, 0.5>
}

difference {
    sphere { 0, 0.6 }
    sphere { 0, 0.6 - 1e-6 }
    pigment { rgbf <0.7, 1, 0.7, 0.8> }
    finish { specular 0.6 reflection 0.15 }
    interior { ior 1.3 }
    translate <0, 0.7, 0.6>
}

// A tinted translucent slab floating 5e-4 above the floor.
box { <-0.6, 5e-4, -0.5>, <0.6, 0.0105, 0.5>
    pigment { rgbf <0.3, 0.5, 1, 0.7> }
    rotate y * -30
    translate <2.1, 0, -0.8>
}

blob {
    threshold 1e-6
    sphere { <0, 0, 0>, 0.5, 1 }
    sphere { <0, 0, 1.0>, 0.5, 1 }
    pigment { rgbf <1, 0.8, 0.3, 0.85> }
    finish { specular 0.4 }
    rotate y * 25
    translate <0.2, 0.3, -2.4>
}

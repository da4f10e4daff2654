// Fading glass as povray 3.7 shades it (facts from its trace.cpp): the
// fade of a stretch inside an interior applies only to what crosses, or is
// totally reflected at, a surface of the object owning that interior;
// a cavity cut by an object without an interior of its own (it gets a
// plain one) does not fade; a reflection is never faded by the stretch
// before it; where the light is totally reflected inside, the reflection
// term of the surface gives way to the mirrored ray.
//  - left: a fading glass block carved by a box with a translucent,
//    reflective skin and no interior (advanced/glasschess's pieces);
//  - right: a fading glass block with fresnel reflection {0.1, 1} seen
//    through its top, over a checker (advanced/wineglass's glass).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 3, -6> look_at <0, 0.8, 0> angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.8, 0.5, 0.3>] [1 rgb <0.3, 0.4, 0.9>] } } }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.2, 0.3, 0.5> scale 0.4 } }

difference {
    box { <-0.8, 0, -0.8>, <0.8, 1.8, 0.8>
        texture { pigment { rgbf <0.95, 1, 0.95, 1> }
                  finish { ambient 0 diffuse 0 specular 1 roughness 0.001 reflection { 0, 1 fresnel } } }
        interior { ior 1.5 fade_distance 1 fade_power 2 fade_color rgb <0.2, 0.5, 0.9> } }
    box { <-0.4, 0.5, -0.4>, <0.4, 1.3, 0.4> rotate y * 20 texture { pigment { rgbt <0.9, 0.8, 0.4, 0.6> } finish { reflection 0.3 } } }
    rotate y * 30
    translate <-1.3, 0.05, 0.3>
}

box { <-0.7, 0, -0.7>, <0.7, 1.4, 0.7>
    texture { pigment { rgbf <1, 1, 1, 0.95> }
              finish { ambient 0.05 diffuse 0.1 specular 0.8 roughness 0.005
                       reflection { 0.1, 1 fresnel } } }
    interior { ior 1.4 fade_distance 0.8 fade_power 1001 fade_color rgb <0.9, 0.3, 0.3> }
    rotate y * -25
    translate <1.3, 0.05, 0.2>
}

// Conformance: planes from every side. A closed "room" of six planes with
// the light inside, so the renderer must light planes seen from their back
// side (the ceiling's normal points away from the viewer), normalise a
// non-unit plane normal (the right wall) and handle a negative distance.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 2, -4.5>
    look_at <0, 1.6, 0>
    angle 80
}

light_source { <-0.5, 3.2, -1> color rgb <1, 0.95, 0.85> }

plane { y, 0 pigment { color rgb <0.7, 0.6, 0.5> } }              // floor
plane { y, 4 pigment { color rgb <0.9, 0.9, 0.9> } }              // ceiling (normal away)
plane { -z, -4 pigment { color rgb <0.5, 0.7, 0.6> } }            // back wall at z = 4
plane { <0, 0, 1>, -5 pigment { color rgb <0.6, 0.6, 0.6> } }     // behind camera
plane { x, -3 pigment { color rgb <0.8, 0.45, 0.4> } }            // left wall
plane { <2, 0, 0>, 3 pigment { color rgb <0.4, 0.5, 0.85> } }     // right wall, non-unit normal

sphere { <1, 0.8, 1.5>, 0.8 pigment { color rgb <0.95, 0.85, 0.4> } }
box { <-2.2, 0, 1>, <-1, 1.4, 2.4> pigment { color rgb <0.35, 0.35, 0.4> } }

// Conformance: finish parameters. A row of spheres with increasing
// phong_size (broad to tight highlights) and a row with different
// ambient/diffuse/phong amounts. Camera uses direction (zoom by length)
// together with look_at instead of angle.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3.5, -9>
    direction 1.5 * z
    look_at <0, 1, 0>
}

light_source { <-6, 8, -8> color rgb <1, 1, 1> }
light_source { <6, 5, -6> color rgb <0.3, 0.3, 0.35> }

plane { y, 0 pigment { color rgb <0.5, 0.5, 0.55> } finish { ambient 0.2 diffuse 0.5 } }

// Back row: same colour, phong 0.9, phong_size 5 / 20 / 60 / 200.
sphere { <-3, 1.9, 1.5>, 0.9 pigment { color rgb <0.8, 0.2, 0.2> } finish { phong 0.9 phong_size 5 } }
sphere { <-1, 1.9, 1.5>, 0.9 pigment { color rgb <0.8, 0.2, 0.2> } finish { phong 0.9 phong_size 20 } }
sphere { <1, 1.9, 1.5>, 0.9 pigment { color rgb <0.8, 0.2, 0.2> } finish { phong 0.9 phong_size 60 } }
sphere { <3, 1.9, 1.5>, 0.9 pigment { color rgb <0.8, 0.2, 0.2> } finish { phong 0.9 phong_size 200 } }

// Front row: ambient only, diffuse only, strong ambient + weak diffuse,
// and a phong highlight on a box face.
sphere { <-3, 0.7, -1.5>, 0.7 pigment { color rgb <0.3, 0.5, 0.9> } finish { ambient 1 diffuse 0 } }
sphere { <-1, 0.7, -1.5>, 0.7 pigment { color rgb <0.3, 0.5, 0.9> } finish { ambient 0 diffuse 1 } }
sphere { <1, 0.7, -1.5>, 0.7 pigment { color rgb <0.3, 0.5, 0.9> } finish { ambient 0.5 diffuse 0.3 phong 0.4 } }
box {
    <2.4, 0, -2.1>, <3.6, 1.2, -0.9>
    rotate y * 20
    pigment { color rgb <0.9, 0.8, 0.3> }
    finish { ambient 0.1 diffuse 0.7 phong 1 phong_size 10 }
}

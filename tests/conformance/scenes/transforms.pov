// Conformance: translate / rotate / scale in several orders on every shape.
// Non-uniform scale turns spheres into ellipsoids (normals must be
// transformed with the inverse transpose); rotate-after-translate orbits an
// object about the origin; planes are rotated and translated too.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 3, -8>
    look_at <0, 1, 0>
    angle 60
}

light_source { <-4, 10, -7> color rgb <1, 1, 1> }

plane { y, 0 pigment { color rgb <0.7, 0.7, 0.75> } }

// Back wall: a plane facing -z, tilted about y and pushed back.
plane {
    z, 0
    rotate y * -25
    translate z * 4
    pigment { color rgb <0.55, 0.6, 0.7> }
}

// Ellipsoid: scale first, then tilt, then place.
sphere {
    <0, 0, 0>, 1
    scale <1.6, 0.6, 0.8>
    rotate z * 30
    translate <-2.2, 1.4, 0>
    pigment { color rgb <0.95, 0.45, 0.2> }
    finish { phong 0.6 phong_size 30 }
}

// Translate then rotate: ends up orbited 40 degrees around the y axis.
box {
    <-0.5, 0, -0.5>, <0.5, 1.2, 0.5>
    translate x * 2.5
    rotate y * -40
    pigment { color rgb <0.3, 0.8, 0.4> }
}

// Uniform float scale of an off-centre sphere also scales its position.
sphere {
    <0.8, 1, -2>, 0.8
    scale 0.75
    translate <0.2, 0, 0>
    pigment { color rgb <0.8, 0.3, 0.8> }
}

// Rotation about several axes at once (x, then y, then z) then scale.
box {
    <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5>
    rotate <30, 45, 10>
    scale <1.2, 1, 0.8>
    translate <0.3, 2.6, 1.2>
    pigment { color rgb <0.9, 0.85, 0.3> }
}

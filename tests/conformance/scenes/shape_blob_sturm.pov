// Conformance: blobs solved with `sturm`: a chain of spheres with
// alternating strengths (one negative), and a ring of cylinders; the same
// blob without sturm beside it.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -7> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, -1 pigment { color rgb <0.75, 0.75, 0.7> } }

#declare Chain = blob {
    threshold 0.45
    #for (I, 0, 5)
        sphere { <I * 0.45 - 1.1, 0.2 * sin(I), 0>, 0.7, (mod(I, 3) = 2 ? -0.6 : 1.1) }
    #end
}
object { Chain sturm translate <-1.3, 0.6, 0.5> pigment { color rgb <0.9, 0.5, 0.2> } finish { phong 0.5 } }
object { Chain translate <-0.6, -0.3, -1.4> pigment { color rgb <0.9, 0.85, 0.3> } finish { phong 0.5 } }
blob {
    threshold 0.5
    #for (I, 0, 5)
        cylinder { <cos(I * pi / 3), 0, sin(I * pi / 3)>, <cos((I + 1) * pi / 3), 0, sin((I + 1) * pi / 3)>, 0.35, 1 }
    #end
    sturm
    rotate x * -50 translate <1.8, 0.3, 0.8>
    pigment { color rgb <0.3, 0.5, 0.95> } finish { phong 0.3 }
}

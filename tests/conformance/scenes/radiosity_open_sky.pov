// A radiosity sample whose rays all miss (they see only the sky) keeps
// povray 3.7's "nothing found" distance (2e10) and no direction toward a
// nearest surface, so its reach is not stretched along any direction.
// frameray had stretched it without end along +z: the open floor's samples
// then served the floor by the glowing wall far ahead.
#version 3.7;
global_settings {
  assumed_gamma 1
  radiosity { count 30 error_bound 1.8 recursion_limit 1 nearest_count 1
              pretrace_start 0.1 pretrace_end 0.1 }
}
camera { location <0, 3, -6> look_at <0, 0, 4> }
sky_sphere { pigment { gradient y color_map { [0 rgb 0.1] [1 rgb <0.5, 0.7, 1.2>] } } }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 0.9 } }
box { <-6, 0, 6>, <6, 2, 6.5> pigment { rgb <1.5, 0.6, 0.2> } finish { ambient 0 diffuse 0 emission 1 } }

// Radiosity rays see no media unless the radiosity block says `media on`:
// a room under radiosity sits inside a large hollow shell of strongly
// emitting media (visible to camera rays through the open front) and a
// small emitting media ball hangs by the light. povray's indirect light on
// the walls is that of the light alone; were the media seen by radiosity
// rays, the room would be washed out.
#version 3.7;
global_settings { assumed_gamma 1
  radiosity { count 300 recursion_limit 1 nearest_count 10 error_bound 0.4
              pretrace_start 0.08 pretrace_end 0.02 } }
camera { location <0, 1.5, -4.5> look_at <0, 1, 0> angle 60 }
light_source { <0.5, 2.5, -0.5> rgb 1 }
#declare F = finish { ambient 0 diffuse 0.8 }
// floor, back and side walls; the front is open to the shell
box { <-2, -0.01, -2>, <2, 0, 2> pigment { rgb 0.8 } finish { F } }
box { <-2, 0, 2>, <2, 3, 2.01> pigment { rgb 0.8 } finish { F } }
box { <-2.01, 0, -2>, <-2, 3, 2> pigment { rgb <0.8, 0.2, 0.1> } finish { F } }
box { <2, 0, -2>, <2.01, 3, 2> pigment { rgb <0.1, 0.3, 0.8> } finish { F } }
box { <-2, 3, -2>, <2, 3.01, 2> pigment { rgb 0.8 } finish { F } }
sphere { <0, 0.5, 0.5>, 0.5 pigment { rgb <0.9, 0.8, 0.3> } finish { F } }
sphere { <0.5, 2.5, -0.5>, 0.2 pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { emission rgb 3 } } hollow no_shadow }
difference {
  sphere { 0, 60 } sphere { 0, 59 }
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { emission rgb <0.6, 0.7, 1> } } hollow no_shadow
}

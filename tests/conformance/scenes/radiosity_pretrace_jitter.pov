// povray 3.7 moves each radiosity pretrace spot within its cell by numbers
// from a fixed cycle of 2047 (the first outputs of a Mersenne twister),
// each tile of each pass walking it from its own start (17 pass + 13 tile),
// y before x. With one coarse pass and a large error_bound the final pass
// reuses the pretrace's samples, so where the spots landed shows: a floor
// lit by a bright sky and a row of glowing posts.
#version 3.7;
global_settings {
  assumed_gamma 1
  radiosity { count 30 error_bound 1.8 recursion_limit 1 nearest_count 1
              pretrace_start 0.2 pretrace_end 0.2 }
}
camera { location <0, 2.5, -4> look_at <0, 0, 1> }
sky_sphere { pigment { gradient y color_map { [0 rgb 0.2] [1 rgb <0.6, 0.8, 1.5>] } } }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 0.9 } }
#declare I = 0;
#while (I < 9)
  box { <-4 + I, 0, 0.5>, <-3.8 + I, 1.5, 0.7>
        pigment { rgb <mod(I, 3) / 2, 1 - mod(I, 2), 0.5> } finish { ambient 0 diffuse 0 emission 1.5 } }
  #declare I = I + 1;
#end

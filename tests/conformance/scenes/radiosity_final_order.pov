// povray 3.7 at +WT1 renders the final pass block by block, each block
// seeing the samples earlier blocks gathered and going on through the
// pool of directions where they left it. frameray settles its blocks in
// that order (render/radiosity_final_pass.h), whatever its thread count.
// One coarse pretrace pass leaves the final pass many samples to gather
// (28 in povray) across the image's six blocks.
#version 3.7;
global_settings {
  assumed_gamma 1
  radiosity { count 30 error_bound 1.5 recursion_limit 1 nearest_count 3
              pretrace_start 0.16 pretrace_end 0.16 }
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

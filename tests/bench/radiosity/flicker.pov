// Radiosity flicker: a static room seen by an orthographic camera that
// moves sideways by exactly one pixel per frame, so consecutive frames
// show the same picture shifted by one pixel; whatever else changes
// between them is flicker.
#version 3.7;
global_settings { assumed_gamma 1 radiosity { count 60 error_bound 0.5 recursion_limit 2 pretrace_start 0.08 pretrace_end 0.02 nearest_count 5 } }
#declare PixelSize = 16 / 3 / image_width;
camera { orthographic location <-1 + frame_number * PixelSize, 2, -5.5> look_at <-1 + frame_number * PixelSize, 2, 0>
         right 16 / 3 * x up 4 * y }
light_source { <-3, 3.5, -2> rgb 1.2 }
box { <-6, 0, -6>, <6, 4, 6> inverse texture { pigment { rgb <0.85, 0.8, 0.7> } finish { ambient 0 diffuse 0.7 } } }
box { <-1, 0, -1>, <1, 2, 1> rotate y * 30 translate <1, 0, 1> texture { pigment { rgb <0.9, 0.2, 0.1> } finish { ambient 0 diffuse 0.7 } } }
sphere { <-2.5, 1, -1>, 1 texture { pigment { rgb <0.2, 0.5, 0.9> } finish { ambient 0 diffuse 0.7 } } }

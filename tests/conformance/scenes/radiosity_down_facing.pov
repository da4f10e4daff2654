// Where the surface faces +y or -y (within 0.001) povray 3.7 takes its pool
// of radiosity directions as they are, or negated, instead of turning them
// into its usual frame (read from its source; the usual frame would mirror
// z under a ceiling). A ceiling seen from below gathers from a floor that
// glows red toward +z and blue toward -z, few rays per sample and no reuse.
#version 3.7;
global_settings {
  assumed_gamma 1
  radiosity { count 5 nearest_count 1 error_bound 0.02 recursion_limit 1
              minimum_reuse 0.0001 maximum_reuse 0.0002 pretrace_start 0.1 pretrace_end 0.1 }
}
camera { location <0, 0.2, -1> look_at <0, 1, 1> }
plane { -y, -1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
plane { y, -0.5 no_image
        pigment { gradient z color_map { [0 rgb <0, 0.2, 1>] [0.5 rgb <0.2, 1, 0.2>] [1 rgb <1, 0.2, 0>] }
                  scale 4 translate -2 * z }
        finish { ambient 0 diffuse 0 emission 1 } }

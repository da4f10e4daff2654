// light_group (povray 3.7): a group's lights light only its own objects;
// they see the scene's lights too with global_lights on (the outermost
// group decides for nested ones); every object shadows every light. Light
// sources inside a union move with it and light the whole scene.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.6, 0> angle 55 }
light_source { <-6, 10, -8> rgb 0.6 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 } }

// A lamp: a union holding its light, moved as one; lights the whole scene.
union {
  light_source { <0, 0.9, 0> rgb <1, 0.8, 0.5> fade_distance 2 fade_power 2 }
  cylinder { <0, 0, 0>, <0, 0.5, 0>, 0.05 pigment { rgb 0.2 } }
  translate <2.8, 0, -1.5>
}

// A declared group: a red key light for one sphere and a box; the same
// members again, seeing the scene's lights too.
#macro Members()
  light_source { <-3, 5, -6> rgb <1, 0.3, 0.2> }
  sphere { <0, 0.8, 0>, 0.8 pigment { rgb 1 } finish { phong 0.6 } }
  box { <-0.3, 0, -1.2>, <0.3, 0.4, -0.8> pigment { rgb <0.4, 0.9, 0.5> } }
#end
#declare Group = light_group { Members() }
object { Group translate x * -2.2 }
light_group { Members() global_lights on translate x * 0.2 }

// Nested: the inner sphere sees the inner blue light only, plus the
// scene's because the outer group has global_lights on.
light_group {
  light_source { <4, 6, -4> rgb <0.3, 1, 0.3> }
  sphere { <2.4, 0.5, 1.2>, 0.5 pigment { rgb 1 } }
  light_group {
    light_source { <6, 3, -2> rgb <0.3, 0.4, 1> }
    sphere { <2.6, 0.4, -0.2>, 0.4 pigment { rgb 1 } }
    global_lights off
  }
  global_lights on
}

// global_lights belongs to a light_group statement: povray 3.7 refuses it
// in object { GROUP } ("No matching } in 'object', global_lights found
// instead").
#version 3.7;
#declare Group = light_group {
    light_source { <0, 5, 0> rgb 1 }
    sphere { 0, 1 pigment { rgb 1 } }
}
object { Group global_lights on }

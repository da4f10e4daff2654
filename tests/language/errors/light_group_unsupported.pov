// light_group is not supported yet: it must stop the render with an error
// naming it, never render the group's objects under the wrong lights.
#version 3.7;
light_group {
    light_source { <0, 5, 0> rgb 1 }
    sphere { 0, 1 pigment { rgb 1 } }
}

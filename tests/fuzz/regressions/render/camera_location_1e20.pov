camera { location <0,1e20,-3> look_at 0 }
light_source { <0,10,-10> rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }
plane { y, -1 pigment { rgb <1,0,0> } }
background { rgb <0,0,1> }

camera { location <0,1,-3> look_at 0 }
light_source { <pow(-8,1/3),1,1> rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }

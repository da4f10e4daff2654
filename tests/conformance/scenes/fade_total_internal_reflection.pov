// Total internal reflection inside a fading interior: the mirrored ray's
// light fades on the way to the surface as the refracted ray's does
// (incdemo/glasses/glass.pov's blue glass pieces). No reflection term,
// so all the light mirrored inside comes from total internal reflection.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
light_source { <10, 10, -5>*1000 color rgb 1.1 }
camera { location <0, 40, -60> direction z right (4/3)*x look_at 3*y angle 12 }
plane { y, 0 pigment { checker rgb 1 rgb 0.7 scale 2 } finish { ambient 0.15 diffuse 0.8 } }
#declare Glass = material { texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } }
                            interior { ior 1.5 fade_distance 2 fade_power 2 fade_color <0.5, 0.5, 1> } }
cone { y*1.9, 1, y*4.1, 0.5 translate -1.4*x material { Glass } }
box { <-1, 0.2, -1>, <1, 3, 1> rotate 30*y translate 1.6*x material { Glass } }

// Conformance: checker with default colours, colours, nested pigments and
// pigment-local transforms on top of object transforms.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }

plane { y, 0 pigment { checker color rgb <0.9, 0.9, 0.8> color rgb <0.2, 0.3, 0.5> } }
sphere { <-2.2, 1, 0>, 1 pigment { checker scale 0.4 } }
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8>
    texture { pigment { checker pigment { checker rgb 1 rgb <1, 0, 0> scale 0.25 }, pigment { rgb <0, 0.4, 0> } scale 0.8 } }
    rotate y * 30 translate <0.3, 0, 0.5> }
sphere { 0, 1 pigment { checker rgb <1, 1, 0>, rgb <0, 0, 0.6> scale <0.5, 2, 0.5> rotate z * 30 } scale 0.9 translate <2.3, 1, 0> }

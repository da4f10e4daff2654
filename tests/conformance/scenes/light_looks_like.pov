// Conformance: looks_like objects (moved to the light, moved by the
// light's transforms, casting no shadow) on a point light and a spotlight.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 1.5, 0> angle 60 }
#declare Bulb = sphere { 0, 0.3 pigment { rgb <1, 1, 0.7> } finish { ambient 1 diffuse 0 } }
light_source { <0, 0, 0> color rgb <1, 0.9, 0.7> looks_like { Bulb } translate <-1.5, 2.5, 0> }
light_source { <2, 3, -1> color rgb <0.5, 0.6, 1> spotlight point_at <2, 0, 0.5> radius 15 falloff 30
    looks_like { cone { <0, 0, 0>, 0.1, <0, 0.4, 0>, 0.3 pigment { rgb <0.6, 0.7, 1> } finish { ambient 0.8 } } } }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-0.5, 0.6, 0.5>, 0.6 pigment { rgb 1 } }
box { <1.5, 0, 0>, <2.4, 1.0, 0.9> pigment { rgb <1, 0.9, 0.8> } }

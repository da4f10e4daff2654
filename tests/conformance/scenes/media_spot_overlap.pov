// Atmospheric media lit by three spotlights whose cones cross: where
// their volumes overlap along a ray they make one lit piece sampled as
// one interval, as povray 3.7 does (interior/media/media1.pov).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <10, 6, -20> direction <0, 0, 1.5> look_at <0, 4, 0> }
media { scattering { 1, rgb 0.03 } intervals 1 samples 5 }
light_source { <0, 15, 0> color rgb 0.7 media_interaction off shadowless }
#macro Spot(Pos, Colour)
  light_source { Pos color Colour * 2 spotlight point_at <0, 5, 0>
    radius 10 falloff 15 tightness 1 media_attenuation on }
#end
Spot(<-10, 15, -5>, rgb <1, 0.3, 0.3>)
Spot(<0, 15, -5>, rgb <0.3, 1, 0.3>)
Spot(<10, 15, -5>, rgb <0.3, 0.3, 1>)
box { <-20, 0, -20>, <20, 20, 20> pigment { rgb 1 } finish { ambient 0.2 diffuse 0.5 } hollow }
sphere { <0, 5, 0>, 1 pigment { rgb 1 } finish { ambient 0.3 diffuse 0.7 phong 1 } }

// Densities: several multiplying, density_map, declared media and
// densities, two media in one interior, media moving with the object.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at 0 angle 45 }
background { rgb 0 }
#declare D1 = density { spherical scale 0.8 color_map { [0 rgb 0] [1 rgb 1] } }
#declare D2 = density { gradient x color_map { [0 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] [1 rgb <0, 0, 1>] } }
#declare M = media { emission 0.8 intervals 2 samples 6 density { D1 } }
sphere { 0, 1 pigment { rgbt 1 } hollow translate <-1.3, 0.9, 0>
  interior { media { M density { D2 scale 2 translate -x } } } }
sphere { 0, 1 pigment { rgbt 1 } hollow translate <1.3, 0.9, 0>
  interior { media { emission <1, 0.2, 0.2> density { D1 } }
             media { emission <0.2, 0.2, 1> density { D1 translate x*0.4 } } } }
box { -1, 1 pigment { rgbt 1 } hollow
  interior { media { emission 0.7 absorption 0.4
    density { gradient y density_map { [0 D1] [0.5 rgb 0.2] [1 D1 scale 0.5] } } } }
  scale <1, 0.8, 0.8> rotate z*30 translate <-1.3, -1.1, 0> }
box { -1, 1 pigment { rgbt 1 } hollow
  interior { media { emission <0.3, 0.8, 0.3> samples 5 aa_level 4 aa_threshold 0.05
    density { bozo scale 0.4 color_map { [0.4 rgb 0] [0.6 rgb 1] } } } }
  scale 0.8 rotate y*40 translate <1.3, -1.1, 0> }

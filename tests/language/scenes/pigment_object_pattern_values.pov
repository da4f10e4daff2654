// pigment_pattern (the pigment's grey: 0.297 r + 0.589 g + 0.114 b in
// single precision, unclamped, filter and transmit ignored) and the object
// pattern (1 inside, 0 outside, through frequency and phase) through
// pattern functions. Colour-mapped pigments print 6 digits: povray blends
// map colours in single precision, frameray in double (1e-8 apart).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Red = function { pattern { pigment_pattern { rgb <1, 0, 0> } } }
#declare Green = function { pattern { pigment_pattern { rgb <0, 1, 0> } } }
#declare Blue = function { pattern { pigment_pattern { rgb <0, 0, 1> } } }
#declare Ft = function { pattern { pigment_pattern { rgbft <0.5, 0.5, 0.5, 0.5, 0.3> } } }
#declare Over = function { pattern { pigment_pattern { rgb 2 } } }
#declare Neg = function { pattern { pigment_pattern { rgb <-1, 0.2, 0.2> } } }
#declare Grad = function { pattern { pigment_pattern { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0.2>] } } frequency 2 } }
#declare Check = function { pattern { pigment_pattern { checker rgb 1, rgb 0.3 } scale 0.5 } }
#declare Bozo = function { pattern { pigment_pattern { bozo color_map { [0 rgb <0.2, 0.9, 0.1>] [1 rgb <1, 0, 0.6>] } scale 0.7 } } }
#declare Ball = sphere { 0, 1 }
#declare InBall = function { pattern { object { Ball } } }
#declare InBox = function { pattern { object { box { 0, 1 } } frequency 0.5 phase 0.1 } }
#declare InScaled = function { pattern { object { sphere { <1, 0, 0>, 0.5 } } scale 2 } }
#declare InDiff = function { pattern { object { difference { box { -1, 1 } sphere { 0, 0.8 } } } } }
#declare InInverse = function { pattern { object { sphere { 0, 1 inverse } } } }
#declare InPlane = function { pattern { object { plane { y, 0 } } } }
#fopen Out "pigment_object_pattern_values.out" write
#write (Out, "solid: ", str(Red(0, 0, 0), 0, 17), " ", str(Green(0, 0, 0), 0, 17), " ", str(Blue(0, 0, 0), 0, 17), " ",
        str(Ft(0, 0, 0), 0, 17), " ", str(Over(0, 0, 0), 0, 17), " ", str(Neg(0, 0, 0), 0, 17), "\n")
#declare S = seed(9);
#for (I, 0, 14)
  #local P = <rand(S) * 6 - 3, rand(S) * 6 - 3, rand(S) * 6 - 3>;
  #write (Out, "point ", I, ": gradient ", str(Grad(P.x, P.y, P.z), 0, 6), " checker ", str(Check(P.x, P.y, P.z), 0, 12),
          " bozo ", str(Bozo(P.x, P.y, P.z), 0, 6), "\n")
#end
#write (Out, "object: ", InBall(0, 0, 0), " ", InBall(2, 0, 0), " ", InBall(1, 0, 0), " ", InBox(0.5, 0.5, 0.5), " ",
        InBox(1.5, 0.5, 0.5), " ", InScaled(2, 0, 0), " ", InScaled(0.5, 0, 0), " ", InDiff(0, 0, 0), " ",
        InDiff(0.9, 0.9, 0), " ", InInverse(0, 0, 0), " ", InInverse(3, 0, 0), " ", InPlane(0, -1, 0), " ",
        InPlane(0, 1, 0), "\n")
#fclose Out

// List patterns through pattern functions: the index as it is by default
// (cubic gives 0..5), and through frequency, phase and the wave type when
// any of them is given (fmod 1.00001 wrap included).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Cubic = function { pattern { cubic } }
#declare CubicF = function { pattern { cubic frequency 0.1 phase 0.05 } }
#declare Checker = function { pattern { checker } }
#declare CheckerF = function { pattern { checker frequency 0.5 phase 0.1 } }
#declare CheckerS = function { pattern { checker sine_wave } }
#declare CheckerN = function { pattern { checker frequency -1 } }
#declare Hexagon = function { pattern { hexagon } }
#declare HexagonF = function { pattern { hexagon frequency 0.5 } }
#declare Brick = function { pattern { brick } }
#declare BrickF = function { pattern { brick frequency 3 phase 0.2 } }
#declare Ball = function { pattern { object { sphere { 0, 1 } } } }
#declare BallF = function { pattern { object { sphere { 0, 1 } } frequency 2 } }
#fopen Out "list_pattern_function_values.out" write
#write (Out, "cubic: ", Cubic(1, 0.1, 0.1), " ", Cubic(0.1, 1, 0.1), " ", Cubic(0.1, 0.1, 1), " ", Cubic(-1, 0.1, 0.1), " ",
        Cubic(0.1, -1, 0.1), " ", Cubic(0.1, 0.1, -1), "\n")
#write (Out, "cubic frequency: ", str(CubicF(1, 0.1, 0.1), 0, 6), " ", str(CubicF(0.1, -1, 0.1), 0, 6), " ",
        str(CubicF(0.1, 0.1, -1), 0, 6), "\n")
#write (Out, "checker: ", Checker(0.5, 0.5, 0.5), " ", Checker(1.5, 0.5, 0.5), " ", str(CheckerF(1.5, 0.5, 0.5), 0, 6), " ",
        str(CheckerF(0.5, 0.5, 0.5), 0, 6), " ", str(CheckerS(1.5, 0.5, 0.5), 0, 6), " ", str(CheckerN(1.5, 0.5, 0.5), 0, 6), "\n")
#write (Out, "hexagon: ", Hexagon(0, 0, 0), " ", Hexagon(1.5, 0, 0.9), " ", str(HexagonF(1.5, 0, 0.9), 0, 6), "\n")
#write (Out, "brick: ", Brick(1, 1.2, 1), " ", str(BrickF(1, 1.2, 1), 0, 6), "\n")
#write (Out, "object: ", Ball(0, 0, 0), " ", Ball(2, 0, 0), " ", str(BallF(0, 0, 0), 0, 6), "\n")
#fclose Out

// Error test: each function calls the one before it twice, so one call of
// F32 runs about 2^32 calls (povray hangs on this). The cost is known when
// the functions are compiled: refused before evaluating, not after hours.
#version 3.7;
#declare F0 = function(x) { x + 1 }
#declare F1 = function(x) { F0(x) + F0(x) }
#declare F2 = function(x) { F1(x) + F1(x) }
#declare F3 = function(x) { F2(x) + F2(x) }
#declare F4 = function(x) { F3(x) + F3(x) }
#declare F5 = function(x) { F4(x) + F4(x) }
#declare F6 = function(x) { F5(x) + F5(x) }
#declare F7 = function(x) { F6(x) + F6(x) }
#declare F8 = function(x) { F7(x) + F7(x) }
#declare F9 = function(x) { F8(x) + F8(x) }
#declare F10 = function(x) { F9(x) + F9(x) }
#declare F11 = function(x) { F10(x) + F10(x) }
#declare F12 = function(x) { F11(x) + F11(x) }
#declare F13 = function(x) { F12(x) + F12(x) }
#declare F14 = function(x) { F13(x) + F13(x) }
#declare F15 = function(x) { F14(x) + F14(x) }
#declare F16 = function(x) { F15(x) + F15(x) }
#declare F17 = function(x) { F16(x) + F16(x) }
#declare F18 = function(x) { F17(x) + F17(x) }
#declare F19 = function(x) { F18(x) + F18(x) }
#declare F20 = function(x) { F19(x) + F19(x) }
#declare F21 = function(x) { F20(x) + F20(x) }
#declare F22 = function(x) { F21(x) + F21(x) }
#declare F23 = function(x) { F22(x) + F22(x) }
#declare F24 = function(x) { F23(x) + F23(x) }
#declare F25 = function(x) { F24(x) + F24(x) }
#declare F26 = function(x) { F25(x) + F25(x) }
#declare F27 = function(x) { F26(x) + F26(x) }
#declare F28 = function(x) { F27(x) + F27(x) }
#declare F29 = function(x) { F28(x) + F28(x) }
#declare F30 = function(x) { F29(x) + F29(x) }
#declare F31 = function(x) { F30(x) + F30(x) }
#declare F32 = function(x) { F31(x) + F31(x) }
#declare Value = F32(1);

// Language test: colour vectors (rgb rgbf rgbt rgbft srgb srgbf srgbt
// srgbft), colour keyword groups, colour identifiers and arithmetic, colour
// dot items and the "common color pitfalls" of the language reference.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "colors.out" write

// Colours are printed as all five components (red, green, blue, filter,
// transmit); #write cannot print a colour directly.
#macro C5(Label, Colour)
  #write (Out, Label, " <", vstr(5, Colour, ", ", 0, 4), ">\n")
#end
#macro C5x(Label, Colour)
  #write (Out, Label, " <", vstr(5, Colour, ", ", 0, 6), ">\n")
#end

// Colour vectors
#declare C = color rgb <1.0, 0.5, 0.2>;          C5("rgb <1,0.5,0.2>", C)
#declare C = color rgbf <1.0, 0.5, 0.0, 1.0>;    C5("rgbf <1,0.5,0,1>", C)
#declare C = color rgbt <0.1, 0.2, 0.3, 0.4>;    C5("rgbt moves 4th to transmit", C)
#declare C = color rgbft <0.1, 0.2, 0.3, 0.4, 0.5>; C5("rgbft", C)
#declare C = colour rgb <0.3, 0.6, 0.9>;         C5("colour spelling", C)
#declare C = rgb <0.25, 0.5, 0.75>;              C5("without color keyword", C)
#declare C = color <0.1, 0.2, 0.3, 0.4, 0.5>;    C5("bare 5 term vector", C)
#declare C = color rgb 0.4;                      C5("rgb float promotes to 3", C)
#declare C = color rgbf 0.5;                     C5("rgbf float promotes to 4", C)
#declare C = color rgbt 0.5;                     C5("rgbt float promotes to 4", C)
#declare C = color rgbft 0.5;                    C5("rgbft float promotes to 5", C)
#declare C = color rgb x;                        C5("rgb x", C)
#declare C = color rgb <1,2,3>*0.5 + 0.25;       C5("rgb of expression", C)
#declare C = color rgbt <1,0.5,0.2,0.7> * 2;     C5("rgbt then times 2", C)

// Keyword groups
#declare C = color red 1.0 green 0.5;            C5("red 1 green 0.5", C)
#declare C = color blue 1.0 green 1.0;           C5("blue 1 green 1 (Cyan)", C)
#declare C = color green 0.2 red 0.3 transmit 0.4 filter 0.5 blue 0.6; C5("any order", C)
#declare C = color red 1 red 0.25;               C5("repeated keyword", C)
#declare C = color red 0.5*2-0.5;                C5("keyword with expression", C)

// Identifiers and arithmetic
#declare White = rgb <1,1,1>;
#declare Cyan = color blue 1.0 green 1.0;
#declare LightGray = White*0.8;                  C5("LightGray = White*0.8", LightGray)
#declare LightCyan = color Cyan red 0.6;         C5("LightCyan = Cyan red 0.6", LightCyan)
#declare C = rgb <1.0,0.5,0.2>*0.9;              C5("rgb <1,0.5,0.2>*0.9", C)
#declare C = rgb <1.0,0.5,0.2>*<0.9,0.9,0.9>;    C5("times 3 term vector", C)
#declare C = White - Cyan;                       C5("White - Cyan", C)
#declare C = (White + Cyan) / 2;                 C5("(White + Cyan)/2", C)
#declare C = Cyan * <0.5, 0.5, 0.5>;             C5("Cyan * <0.5,0.5,0.5>", C)
#declare C = color Cyan;                         C5("color Cyan", C)
#declare C = color Cyan filter 0.3;              C5("Cyan filter 0.3", C)

// Dot items on colours
#declare Shade = rgbft <0.2, 0.4, 0.6, 0.8, 1.0>;
#write (Out, "dot red green blue ", 0+Shade.red, " ", 0+Shade.green, " ", 0+Shade.blue, "\n")
#write (Out, "dot filter transmit ", 0+Shade.filter, " ", 0+Shade.transmit, "\n")
#write (Out, "dot gray ", str(0+Shade.gray, 0, 6), " ", str(0+White.gray, 0, 6), "\n")
#write (Out, "dot x y z t ", 0+Shade.x, " ", 0+Shade.y, " ", 0+Shade.z, " ", 0+Shade.t, "\n")

// Common color pitfalls
#declare My_Color = rgbft <0.2, 0.4, 0.6, 0.8, 0.9>;
#declare C = color filter 1.0;                   C5("pitfall color filter 1 is black", C)
#declare C = color red 1.0 green 1.0 blue 1.0 filter 1.0; C5("pitfall clear filter", C)
#declare C = color transmit 1.0;                 C5("pitfall color transmit 1", C)
#declare C = color My_Color red 0.5;             C5("pitfall My_Color red 0.5", C)
// POV-Ray 3.7 rejects the other keyword pitfalls of the reference
// ("color My_Color + red 0.5", "color My_Color * red 0.5": a colour keyword
// where a numeric expression is expected; "color red 0.5 My_Color": missing
// semicolon), so they are not tested here.
#declare C = color 0.4;                          C5("pitfall color 0.4", C)
#declare C = color rgb 0.4;                      C5("pitfall color rgb 0.4", C)
// In POV-Ray 3.7 a colour dot item declares a float (the reference still
// describes the older behaviour, a colour of five equal components).
#declare MyColor = rgb <0.75, 0.5, 0.75>;
#declare RedAmt = MyColor.red;
#write (Out, "pitfall RedAmt = MyColor.red is a float ", RedAmt, " ", <0,0,0>+RedAmt, "\n")
#declare RedAmt = 0.0+MyColor.green;
#write (Out, "pitfall RedAmt = 0.0+MyColor.green ", RedAmt, "\n")
#declare RedAmt = 1.0*MyColor.blue;
#write (Out, "pitfall RedAmt = 1.0*MyColor.blue ", RedAmt, "\n")
#declare RedAmt = (MyColor.red);
#write (Out, "pitfall RedAmt = (MyColor.red) ", RedAmt, "\n")

// sRGB colours (after assumed_gamma): converted to linear values
#declare Foo = color srgbt <51,76,102,127>/255;  C5("srgbt doc 1", Foo)
#declare Foo = color srgbt <0.2, 0.3, 0.4, 0.5>; C5("srgbt doc 2", Foo)
#declare Foo = color srgb <0.2, 0.3, 0.4> transmit 0.5; C5("srgb doc 3", Foo)
#declare Foo = color rgbt <0.033,0.073,0.133,0.5>; C5("rgbt doc 4", Foo)
#declare C = color srgb <0, 0.5, 1>;             C5x("srgb 0 0.5 1", C)
#declare C = color srgb <0.002, 0.04045, 0.2>;   C5x("srgb low end", C)
#declare C = color srgb 0.5;                     C5x("srgb float", C)
#declare C = color srgbf <0.5, 0.6, 0.7, 0.3>;   C5x("srgbf keeps filter linear", C)
#declare C = color srgbft <0.5, 0.6, 0.7, 0.3, 0.4>; C5x("srgbft", C)
#declare C = color srgb <2, -0.5, 1.5>;          C5x("srgb out of range", C)
#write (Out, "srgb dot red ", str(0+C.red, 0, 6), "\n")

// POV-Ray keeps colour components in single precision; vectors are doubles.
#declare C = rgb 0.1;
#declare V = <0.1, 0.1, 0.1>;
#write (Out, "precision colour ", vstr(3, C, ",", 0, 12), " vector ", vstr(3, V, ",", 0, 12), "\n")
#write (Out, "precision colour dot item ", str(0+C.green, 0, 12), "\n")

// The standard include file (it switches #version and restores it)
#include "colors.inc"
C5("colors.inc Red", Red)
C5("colors.inc Clear", Clear)
C5("colors.inc Gray50", Gray50)
C5("colors.inc Orange", Orange)
C5("colors.inc SkyBlue", SkyBlue)
#declare C = color Orange blue 0.5;              C5("Orange blue 0.5", C)
C5x("colors.inc CHSV2RGB(<120,1,1>)", CHSV2RGB(<120, 1, 1>))
C5x("colors.inc CHSL2RGB(<240,1,0.25>)", CHSL2RGB(<240, 1, 0.25>))
#write (Out, "version after colors.inc ", version, "\n")
#fclose Out

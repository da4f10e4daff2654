// Language test: syntax forms the standard include files use that are
// easy to miss: a string literal over two lines (shapes3.inc's #warning),
// vector components without commas (woods.inc: < -1 0 0 >), macro
// parameter lists with a trailing comma or a missing comma (shapes3.inc),
// colour-map bands without the comma ([a b color C1 color C2]: woodmaps.inc,
// stars.inc), colour maps with entries out of order (woods.inc T_Wood32),
// object { OBJECT }, declared materials and an array declaration followed
// by a directive.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "include_file_syntax.out" write

#declare S = "ab
cd";
#write (Out, "string over two lines length ", strlen(S), "\n")

#declare V = < -1 0 0 >;
#write (Out, "vector without commas ", V.x, " ", V.y, " ", V.z, "\n")
#declare V = < 1 -2, 3 4 >;
#write (Out, "vector 1 -2 is one component ", V.x, " ", V.y, " ", V.z, "\n")
#declare V = < 1, (2) 3 >;
#write (Out, "vector mixed ", V.x, " ", V.y, " ", V.z, "\n")

#macro Sum3(A, B C,) A + B * 10 + C * 100 #end
#write (Out, "macro trailing and missing commas ", Sum3(1, 2, 3), " ", Sum3(4, 5, 6,), "\n")

#declare F = function { pigment { gradient x color_map {
    [0 0.25 color rgb 0 color rgb 1] [0.25 1 color rgb 1 color rgb 0] } } }
#write (Out, "band without comma ", F(0.125, 0, 0).red, " ", F(0.625, 0, 0).red, "\n")

#declare G = function { pigment { gradient x color_map {
    [0.1 rgb 0] [0.6 rgb 1] [0.4 rgb 0.5] [0.9 rgb 0.2] } } }
#declare I = 0;
#while (I <= 10)
    #write (Out, "unsorted map at ", I / 10, " ", G(I / 10 * 0.999, 0, 0).red, "\n")
    #declare I = I + 1;
#end

#declare O = object { sphere { 0, 1 } translate x }
#write (Out, "object of an object statement ", max_extent(O).x, "\n")
#declare O = object { object { box { 0, 1 } scale 2 } translate -y }
#write (Out, "nested object statements ", max_extent(O).x, " ", min_extent(O).y, "\n")

#declare M = material { texture { pigment { rgb <0.2, 0.4, 0.6> } } interior { ior 1.5 } scale 2 }
#declare M2 = material { M }
#declare O = sphere { 0, 1 material { M2 } translate y }
#write (Out, "object with a declared material ", max_extent(O).y, "\n")

// An array declared without ';' or initializer, then assigned by the
// next line's directive (shapes.inc's HF_Square, with a #local array).
#declare Arr = array[2][2]
#declare Arr[1][1] = 5;
#macro LocalArray()
    #local L = array[3]
    #declare L[2] = 7;
    L[2]
#end
#write (Out, "array element after the declaration ", Arr[1][1], " ", LocalArray(), "\n")
#fclose Out

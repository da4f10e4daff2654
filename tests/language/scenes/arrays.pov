// Language test: arrays of one to five dimensions, initializers,
// dimensions() and dimension_size(), #ifdef/#ifndef on elements, element
// assignment, arrays of strings and vectors, copies and arrays in macros.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "arrays.out" write

// One dimension, element by element
#declare MyArray = array[10];
#write (Out, "1d dimensions ", dimensions(MyArray), " size ", dimension_size(MyArray, 1), "\n")
#ifdef (MyArray[5]) #write (Out, "1d ifdef unset element true\n") #else #write (Out, "1d ifdef unset element false\n") #end
#declare MyArray[5] = 55;
#ifdef (MyArray[5]) #write (Out, "1d ifdef set element true\n") #else #write (Out, "1d ifdef set element false\n") #end
#ifndef (MyArray[4]) #write (Out, "1d ifndef unset element true\n") #end
#declare MyArray[0] = 1.5;
#declare MyArray[9] = MyArray[5] * 2;
#write (Out, "1d elements ", MyArray[0], " ", MyArray[5], " ", MyArray[9], "\n")
#declare MyArray[2.9] = 29;
#write (Out, "1d index truncated ", MyArray[2], "\n")
#declare Idx = 4;
#declare MyArray[Idx + 0.5] = Idx * 10;
#write (Out, "1d index expression ", MyArray[Idx], " ", MyArray[Idx*2+1], "\n")
#declare MyArray[5] = MyArray[5] + 1;
#write (Out, "1d element reassigned ", MyArray[5], "\n")
#write (Out, "1d defined() of identifier ", defined(MyArray), "\n")

// Initializers
#declare Flags = array[3] {"Red", "White", "Blue"}
#write (Out, "init strings ", Flags[0], " ", Flags[1], " ", Flags[2], "\n")
#declare Points = array[3] {<1,2,3>, x, 2*y+z}
#write (Out, "init vectors ", Points[0], " ", Points[1], " ", Points[2], "\n")
#declare Expr = array[4] {1+1, pi, sqrt(16), -2*3}
#write (Out, "init expressions ", Expr[0], " ", Expr[1], " ", Expr[2], " ", Expr[3], "\n")
#declare Digits =
array[4][10] {
  {7,6,7,0,2,1,6,5,5,0},
  {1,2,3,4,5,6,7,8,9,0},
  {0,9,8,7,6,5,4,3,2,1},
  {1,1,2,2,3,3,4,4,5,5}
}
#write (Out, "2d dimensions ", dimensions(Digits), " sizes ", dimension_size(Digits, 1), " ", dimension_size(Digits, 2), "\n")
#write (Out, "2d rows:")
#for (R, 0, 3)
  #write (Out, " ")
  #for (C, 0, 9) #write (Out, Digits[R][C]) #end
#end
#write (Out, "\n")
#declare Sum = 0;
#for (R, 0, 3) #for (C, 0, 9) #declare Sum = Sum + Digits[R][C]; #end #end
#write (Out, "2d sum ", Sum, "\n")
#declare Digits[2][3] = 99;
#write (Out, "2d assigned element ", Digits[2][3], "\n")

// Three to five dimensions
#declare Cube = array[2][3][4];
#for (I, 0, 1) #for (J, 0, 2) #for (K, 0, 3)
  #declare Cube[I][J][K] = I*100 + J*10 + K;
#end #end #end
#write (Out, "3d dimensions ", dimensions(Cube), " sizes ", dimension_size(Cube, 1), dimension_size(Cube, 2), dimension_size(Cube, 3), "\n")
#write (Out, "3d elements ", Cube[0][0][0], " ", Cube[1][2][3], " ", Cube[1][0][2], "\n")
#declare Init3 = array[2][2][2] { { {1, 2}, {3, 4} }, { {5, 6}, {7, 8} } }
#write (Out, "3d initializer ", Init3[0][0][0], Init3[0][0][1], Init3[0][1][0], Init3[0][1][1], Init3[1][0][0], Init3[1][0][1], Init3[1][1][0], Init3[1][1][1], "\n")
#declare Four = array[2][1][3][2];
#declare Four[1][0][2][1] = 4321;
#write (Out, "4d dimensions ", dimensions(Four), " sizes ", dimension_size(Four, 1), dimension_size(Four, 2), dimension_size(Four, 3), dimension_size(Four, 4), " element ", Four[1][0][2][1], "\n")
#ifdef (Four[0][0][0][0]) #write (Out, "4d ifdef unset true\n") #else #write (Out, "4d ifdef unset false\n") #end
#declare Five = array[2][2][2][2][3] {
  { { { {1,2,3}, {4,5,6} }, { {7,8,9}, {10,11,12} } },
    { { {13,14,15}, {16,17,18} }, { {19,20,21}, {22,23,24} } } },
  { { { {25,26,27}, {28,29,30} }, { {31,32,33}, {34,35,36} } },
    { { {37,38,39}, {40,41,42} }, { {43,44,45}, {46,47,48} } } }
}
#write (Out, "5d dimensions ", dimensions(Five), " sizes ", dimension_size(Five, 1), dimension_size(Five, 2), dimension_size(Five, 3), dimension_size(Five, 4), dimension_size(Five, 5), "\n")
#write (Out, "5d elements ", Five[0][0][0][0][0], " ", Five[1][1][1][1][2], " ", Five[1][0][1][0][1], " ", Five[0][1][0][1][2], "\n")
#ifdef (Five[1][1][1][1][2]) #write (Out, "5d ifdef initialised true\n") #end

// Arrays as values: copies, macros, arrays of arrays
#declare Original = array[3] {1, 2, 3}
#declare Copy = Original;
#declare Copy[0] = 100;
#write (Out, "copy is independent ", Original[0], " ", Copy[0], " size ", dimension_size(Copy, 1), "\n")
#macro SumArray(A)
  #local S = 0;
  #for (I, 0, dimension_size(A, 1) - 1) #local S = S + A[I]; #end
  S
#end
#write (Out, "array passed to macro ", SumArray(Original), " ", SumArray(array[4] {1, 10, 100, 1000}), "\n")
#macro FillSquares(A)
  #for (I, 0, dimension_size(A, 1) - 1) #declare A[I] = I * I; #end
#end
#declare Squares = array[6];
FillSquares(Squares)
#write (Out, "array filled by macro ", Squares[0], " ", Squares[3], " ", Squares[5], "\n")
#macro MakeArray(N)
  #local Result = array[N];
  #for (I, 0, N - 1) #local Result[I] = N - I; #end
  Result
#end
#declare Made = MakeArray(4);
#write (Out, "array returned by macro ", dimension_size(Made, 1), ": ", Made[0], Made[1], Made[2], Made[3], "\n")
#declare Colours = array[2] {rgb <1,0,0>, rgbt <0,0.5,1,0.25>}
#write (Out, "array of colours ", vstr(5, Colours[1], ",", 0, 2), "\n")
#local LocalArray = array[2] {5, 6}
#write (Out, "local array ", LocalArray[0] + LocalArray[1], "\n")
#declare Str = array[2] {"x", "y"}
#write (Out, "string elements concat ", concat(Str[0], Str[1], Str[0]), "\n")
#declare Vecs = array[2] {<1,2,3>, <4,5,6>}
#write (Out, "vector element dot item ", Vecs[1].y, " ", Vecs[0].z + Vecs[1].x, "\n")
#undef Vecs
#write (Out, "undef array ", defined(Vecs), "\n")
#declare Nested = array[2];
#declare Nested[0] = array[2] {"a", "b"}
#declare Nested[1] = array[3] {"c", "d", "e"}
#write (Out, "array of arrays ", Nested[0][1], Nested[1][2], " sizes ", dimension_size(Nested[0], 1), " ", dimension_size(Nested[1], 1), "\n")
#fclose Out

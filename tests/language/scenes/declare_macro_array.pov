// A #declare whose value is an array returned by a macro (advanced/
// benchmark/benchmark.pov): the macro's #end returns to the declaration,
// which binds the identifier before the next directive runs, with or
// without a ';' and whether the macro returns its own #local or a global.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "declare_macro_array.out" write
#declare G = array[2] {10, 20}
#macro Global() G #end
#macro Built(N)
    #local A = array[N + 1][2]
    #local I = 0;
    #while (I <= N)
        #local A[I][0] = I;
        #local A[I][1] = I * I;
        #local I = I + 1;
    #end
    A
#end
#macro User(N)
    #declare Inner = Built(N)
    #local Dim = dimension_size(Inner, 1);
    #write (Out, "inside a macro: ", Dim, " rows, last ", Inner[Dim - 1][1], "\n")
#end
#declare X = Global()
#write (Out, "global: ", X[1], "\n")
#declare Y = Built(3)
#write (Out, "local: ", dimension_size(Y, 1), " rows, ", Y[2][1], "\n")
#declare Z = Built(2);
#write (Out, "with ';': ", Z[2][1], "\n")
User(4)
#fclose Out

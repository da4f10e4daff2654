// Language test: povray reads the commas of a #write list as optional, also
// the one after the file identifier (the example portfolio's html_gen.inc
// writes `#write(HTMLFile Header1)`), and warns about none of them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Head = "<head>";
#fopen Out "write_without_commas.out" write
#write(Out Head "\n")
#write(Out Head, "a" "b\n")
#write(Out "n=" 1 " v=" <1,2,3> "\n")
#write(Out "sum " 1 -2 " (one expression)\n")
#write(Out, "trailing comma\n",)
#write(Out concat("x", "y") str(3, 0, 1) "\n")
#fclose Out

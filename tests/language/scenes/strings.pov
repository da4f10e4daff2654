// Language test: string literals and escapes, string identifiers, the
// string functions str, concat, chr, substr, strupr, strlwr and vstr, and
// string comparison.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "strings.out" write

// Literals and escape sequences
#write (Out, "plain [Here There]\n")
#write (Out, "escaped quote [Joe said \"Hello\" as he walked in.]\n")
#write (Out, "escaped backslash [This is a backslash \\ and this is two \\\\]\n")
#write (Out, "escaped tab [a\tb] single quote [\'] \n")
#write (Out, "unicode escape [\u0041\u0062]\n")
#write (Out, "empty [", "", "]\n")
#write (Out, "several items [", "a", "b", "c", "]\n")

// str(A, L, P)
#write (Out, "str doc [", str(123.456, 0, 3), "][", str(123.456, 4, 3), "][", str(123.456, 9, 3), "][", str(123.456, -9, 3), "]\n")
#write (Out, "str doc [", str(123.456, 0, 2), "][", str(123.456, 0, 0), "][", str(123.456, 5, 0), "][", str(123.000, 7, 2), "]\n")
#write (Out, "str default precision [", str(123.456, 0, -1), "][", str(1/3, 0, -1), "]\n")
#write (Out, "str negative [", str(-1.5, 0, 2), "][", str(-1.5, 8, 2), "][", str(-1.5, -8, 2), "]\n")
#write (Out, "str rounding [", str(2.5, 0, 0), "][", str(3.5, 0, 0), "][", str(0.125, 0, 2), "][", str(0.375, 0, 2), "][", str(1.005, 0, 2), "]\n")
#write (Out, "str large [", str(1e10, 0, 1), "][", str(123456789, 0, 0), "]\n")
#write (Out, "str small [", str(0.000123, 0, 6), "][", str(1e-7, 0, 3), "]\n")
#write (Out, "str truncates L and P [", str(2.25, 6.9, 1.9), "]\n")
#write (Out, "str of expression [", str(2*pi, 0, 5), "]\n")

// concat, chr, substr, strupr, strlwr
#write (Out, "concat [", concat("a", "b"), "][", concat("Value is ", str(12.34321, 3, 1), " inches"), "]\n")
#write (Out, "concat many [", concat("1", "2", "3", "4", "5", "6"), "]\n")
#write (Out, "concat empty [", concat("", "x", ""), "]\n")
#write (Out, "chr [", chr(70), chr(111), chr(111), "][", chr(32), "][", chr(126), "]\n")
#write (Out, "chr of float [", chr(65.7), "]\n")
#write (Out, "substr [", substr("ABCDEFGHI", 4, 2), "][", substr("Hello", 1, 5), "][", substr("Hello", 5, 1), "][", substr("Hello", 2, 0), "]\n")
#write (Out, "substr float args [", substr("ABCDEFGHI", 2.9, 3.9), "]\n")
#write (Out, "strupr [", strupr("Hello There!"), "]\n")
#write (Out, "strlwr [", strlwr("Hello There! 123"), "]\n")
#declare Original = "MiXeD";
#declare Upper = strupr(Original);
#write (Out, "strupr keeps original [", Original, "][", Upper, "]\n")
#write (Out, "nested functions [", strupr(concat(substr("abcdef", 2, 3), chr(33))), "]\n")
#write (Out, "strlen of str ", strlen(str(pi, 0, 4)), "\n")
#write (Out, "asc of chr ", asc(chr(200)), "\n")

// vstr(N, A, S, L, P)
#write (Out, "vstr doc [", vstr(2, <1,2>, ", ", 0, 1), "][", vstr(5, <1,2,3,4,5>, ", ", 0, 1), "]\n")
#write (Out, "vstr clipped N [", vstr(1, <1,2>, ", ", 0, 1), "][", vstr(7, <1,2,3,4,5>, ", ", 0, 1), "]\n")
#write (Out, "vstr padded [", vstr(3, <1,2>, ", ", 0, 1), "][", vstr(5, <1,2,3>, ", ", 0, 1), "]\n")
#write (Out, "vstr fewer than given [", vstr(2, <1,2,3>, ";", 0, 0), "]\n")
#write (Out, "vstr widths [", vstr(3, <1.5,-2,30>, "|", 6, 2), "][", vstr(3, <1.5,-2,30>, "|", -6, 2), "]\n")
#write (Out, "vstr separator [", vstr(3, x+2*y+3*z, "", 0, 0), "][", vstr(3, <0.5,0.25,0.125>, " and ", 0, 3), "]\n")
#write (Out, "vstr default precision [", vstr(3, <1,2,3>/3, ",", 0, -1), "]\n")

// String comparison (same as strcmp)
#declare TestCase = "ABC";
#write (Out, "compare lt ", ("abc" < "abd"), " ", ("abd" < "abc"), " ", (TestCase < "ABD"), "\n")
#write (Out, "compare le ", ("abc" <= "abc"), " ", ("abd" <= "abc"), "\n")
#write (Out, "compare eq ", ("abc" = "abc"), " ", ("abc" = "ABC"), " ", (TestCase = "ABC"), "\n")
#write (Out, "compare ne ", ("abc" != "abc"), " ", ("A" != "a"), "\n")
#write (Out, "compare ge ", ("b" >= "a"), " ", ("a" >= "b"), " ", ("x" >= "x"), "\n")
#write (Out, "compare gt ", ("b" > "a"), " ", ("ab" > "abc"), " ", ("" > ""), "\n")
#write (Out, "compare with functions ", (concat("a", "b") = "ab"), " ", (strupr("q") = "Q"), "\n")
#if (TestCase < "ABD")
  #write (Out, "compare in #if: ABC < ABD\n")
#else
  #write (Out, "compare in #if: ABC >= ABD\n")
#end
#if (strcmp(TestCase, "ABC") = 0)
  #write (Out, "strcmp in #if: equal\n")
#end

// String identifiers (no semicolon needed) and redeclaration
#declare Name = "John"
#declare Name = concat(Name, " Doe")
#write (Out, "identifier [", Name, "] length ", strlen(Name), "\n")
#local Greeting = "hi";
#write (Out, "local identifier [", Greeting, "]\n")

// Built-in string identifier
#write (Out, "input_file_name [", input_file_name, "]\n")
#fclose Out

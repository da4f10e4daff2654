// Error test: the lexer fails inside an included file (an unterminated
// string). The error outlives the tokens of the include; the message must
// name the include and the line that included it (a fuzzer found this
// reading freed memory).
#version 3.7;
#declare Before = 1;
#include "lex_error_in_include.inc"

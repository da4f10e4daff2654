// Language test: user-defined functions with the default parameters x, y, z,
// explicit parameter lists (u and v as aliases of x and y), the function
// grammar's own operator precedence, built-in float functions inside
// functions, sum() and prod(), functions calling functions, constants
// captured at definition, #undef and redefinition, functions passed to
// macros.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "functions.out" write

#macro W(Label, Value)
  #write (Out, Label, " ", str(Value, 0, 9), "\n")
#end

// Parameters
#declare foo = function { x + y * z }
W("default parameters foo(1,2,3)", foo(1, 2, 3))
W("default parameters foo(2,-1,0.5)", foo(2, -1, 0.5))
#declare foo2 = function(x, y, z) { x + y * z }
W("explicit x,y,z", foo2(1, 2, 3))
#declare foo4 = function(h) { h * h + h }
W("one parameter foo4(3)", foo4(3))
#declare Many = function(a, b, c, d, e, f) { a - b + c * d - e / f }
W("six parameters", Many(1, 2, 3, 4, 5, 10))
#declare Const = function { 2.5 }
W("constant with default parameters", Const(7, 8, 9))
W("in an expression", foo(1, 2, 3) * 2 + foo4(1))
W("arguments are expressions", foo(1 + 1, sqrt(9), foo4(1)))

// Operators inside functions: & binds tighter than |, both lower than
// relational operators
#declare Logic1 = function { 1 | 0 & 0 }
#declare Logic2 = function { 0 & 0 | 1 }
#declare Logic3 = function(a, b) { a < b | a > 2 * b }
W("function 1|0&0", Logic1(0, 0, 0))
W("function 0&0|1", Logic2(0, 0, 0))
W("function relational and or (1,2)", Logic3(1, 2))
W("function relational and or (5,2)", Logic3(5, 2))
W("function relational and or (3,2)", Logic3(3, 2))
#declare Rel = function(a, b) { (a = b) + 2 * (a != b) + 4 * (a <= b) + 8 * (a >= b) }
W("function relations (1,1)", Rel(1, 1))
W("function relations (1,2)", Rel(1, 2))
W("function relations (1,1+1e-12)", Rel(1, 1 + 1e-12))
#declare Prec = function(a) { -a * 2 + 3 / 4 - -a }
W("function precedence", Prec(5))
#declare Paren = function(a, b) { (a + b) * (a - b) / 2 }
W("function parentheses", Paren(7, 3))

// Built-in float functions inside functions
#declare Trig = function(a) { sin(a) * cos(a) + tan(a / 4) + atan2(a, 1) }
W("trig", Trig(1))
#declare Hyper = function(a) { sinh(a) + cosh(a) - tanh(a) + asinh(a) + acosh(a + 1) + atanh(a / 4) }
W("hyperbolic", Hyper(0.5))
#declare Inv = function(a) { asin(a) + acos(a) + atan(a) }
W("inverse trig", Inv(0.5))
#declare Rounding = function(a) { floor(a) * 1000 + ceil(a) * 100 + int(a) * 10 + abs(a) }
W("rounding 2.5", Rounding(2.5))
W("rounding -2.5", Rounding(-2.5))
#declare PowExp = function(a, b) { pow(a, b) + exp(b) + ln(a) + log(a) + sqrt(a) }
W("pow exp ln log sqrt", PowExp(4, 0.5))
#declare ModDiv = function(a, b) { mod(a, b) * 100 + div(a, b) }
W("mod div (17,5)", ModDiv(17, 5))
W("mod div (-17,5)", ModDiv(-17, 5))
#declare MinMax = function(a, b, c) { max(a, b, c) * 10 + min(a, b, c) }
W("min max", MinMax(3, 7, 5))
#declare Sel = function(a) { select(a, -1, 0, 1) * 10 + select(a, 5, 6) }
W("select(-2)", Sel(-2))
W("select(0)", Sel(0))
W("select(2)", Sel(2))
#declare Angles = function(a) { degrees(a) + radians(a) }
W("degrees radians", Angles(pi))
#declare TwoPi = function { pi * 2 }
W("pi inside", TwoPi(0, 0, 0))

// sum() and prod()
#declare factorial = function(C) { prod(i, 1, C, i) }
W("prod factorial(5)", factorial(5))
W("prod factorial(10)", factorial(10))
W("prod factorial(0) empty product", factorial(0))
#declare SumSquares = function(n) { sum(i, 1, n, i * i) }
W("sum of squares 1..10", SumSquares(10))
#declare Fractional = function { sum(k, 0.5, 3, k) }
W("sum with fractional start 0.5..3", Fractional(0, 0, 0))
#declare Nested = function(n) { sum(i, 1, n, sum(j, 1, i, j)) }
W("nested sum", Nested(4))
#declare Harmonic = function(n) { sum(i, 1, n, 1 / i) }
W("harmonic 100", Harmonic(100))
#declare Outside = function(a) { sum(i, 1, 3, i * a) }
W("sum using a parameter", Outside(2))
#declare Empty = function { sum(i, 5, 1, i) }
W("sum over empty range", Empty(0, 0, 0))

// Functions calling functions
#declare F1 = function(a, b) { a * 10 + b }
#declare F2 = function(a) { F1(a, a + 1) * 2 }
#declare F3 = function(a) { F2(F1(a, 0)) - F1(1, 1) }
W("function calls F2(3)", F2(3))
W("function calls F3(1)", F3(1))
#declare Dist = function { sqrt(x*x + y*y + z*z) }
#declare Shell = function { abs(Dist(x, y, z) - 1) }
W("function calls with default parameters", Shell(3, 4, 0))

// Identifiers are constants fixed when the function is defined
#declare K = 2;
#declare Scaled = function(a) { a * K }
#declare K = 3;
W("constant captured at definition", Scaled(5))
#declare Scaled2 = function(a) { a * K }
W("new definition sees the new value", Scaled2(5))

// #undef and redefinition
#undef Scaled
#declare Scaled = function(a) { a / 2 }
W("redefined after #undef", Scaled(5))
#local LocalFn = function(a) { a + 100 }
W("#local function", LocalFn(1))

// Functions passed to macros
#macro Foo(Bar, X)
  #declare Y = Bar(X);
  #declare Z = Bar(Y);
#end
#declare FUNC = function(n) { n + 2 }
Foo(FUNC, 1)
W("function passed to macro Y", Y)
W("function passed to macro Z", Z)
#macro Integrate(Fn, A, B, Steps)
  #local Acc = 0;
  #local H = (B - A) / Steps;
  #for (I, 0, Steps - 1)
    #local Acc = Acc + Fn(A + (I + 0.5) * H) * H;
  #end
  Acc
#end
#declare Parabola = function(q) { q * q }
W("numeric integration of a function", Integrate(Parabola, 0, 3, 300))

// x and u, y and v are the same parameter
#declare foo5 = function(u, v) { x + y * v }
W("u v aliases foo5(2,3) = u + v*v", foo5(2, 3))
#declare foo6 = function(x, v, z) { u + y * v + z }
W("x v z aliases foo6(1,2,3) = x + v*v + z", foo6(1, 2, 3))
#fclose Out

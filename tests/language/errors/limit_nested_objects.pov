// Error test: objects nested past the limit (400 levels) stop the parse
// with an error instead of overflowing the stack.
#version 3.7;
global_settings { assumed_gamma 1.0 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
union { sphere { 0, 1 }
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}

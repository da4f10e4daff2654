// User-defined functions.
#include <fmt/format.h>

#include "sdl/interpreter.h"

namespace frameray::sdl {

struct FunctionValue {};

Value Interpreter::parseFunctionDeclaration() { unsupported(peek(), "function"); }
Value Interpreter::callFunction(const FunctionValue&, const Token& at) { unsupported(at, "function"); }

}  // namespace frameray::sdl

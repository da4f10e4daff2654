// Splines: declaration and evaluation.
#include <fmt/format.h>

#include "sdl/interpreter.h"

namespace frameray::sdl {

struct SplineValue {};

Value Interpreter::parseSpline() { unsupported(peek(), "spline"); }
Value Interpreter::callSpline(const SplineValue&, const Token& at) { unsupported(at, "spline"); }

}  // namespace frameray::sdl

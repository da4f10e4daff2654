// The value of a `function { ... }` declaration.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>

#include "sdl/keywords.h"
#include "util/function_vm.h"

namespace frameray::sdl {

// The vector component a dot item names: 0..4 for .x .y .z .t (and .u .v
// .red .green .blue .filter .transmit), kGrayItem for .gray (POV-Ray's
// grey of the colour), -1 for anything else (expressions.cpp).
inline constexpr int kGrayItem = 5;
int dotItemSlot(Keyword kw);

// A compiled function whose whole body is one native function reading the
// function's own `paramCount` arguments (functions.cpp).
std::shared_ptr<CompiledFunction> nativeBody(std::string name, int paramCount,
                                             std::shared_ptr<const NativeFunction> native);

// A function whose value is a vector: `function { pigment {..} }` (a
// colour of the point x, y, z), `function { transform {..} }` (the point
// transformed) and `function { spline {..} }` (the spline at its one
// argument). Called in an expression it gives the vector; inside another
// function each call picks one component with a dot item (F(x,y,z).gray).
struct VectorFunction {
    std::string kind;  // "pigment", "transform", "spline" (for messages)
    int paramCount = 3;
    int size = 3;  // components of the value
    bool isColor = false;
    // Thread-safe: shapes evaluate it while rendering.
    std::function<std::array<double, 5>(const double* args)> eval;
};

struct FunctionValue {
    std::shared_ptr<const CompiledFunction> compiled;
    // Set instead of `compiled` for a vector-valued function.
    std::shared_ptr<const VectorFunction> vector;
    // Whether calls may pass any number of arguments: functions.inc's
    // `function { internal(N) }` take x, y, z plus their own parameters.
    bool variadic = false;
    // Set for kinds of function body not built yet (functions.inc
    // internals frameray lacks): declaring one is fine, using it stops with
    // `not supported yet: <unsupported>`.
    std::string unsupported;
};

}  // namespace frameray::sdl

// The value of a `function { ... }` declaration.
#pragma once

#include <memory>
#include <string>

#include "util/function_vm.h"

namespace frameray::sdl {

struct FunctionValue {
    std::shared_ptr<const CompiledFunction> compiled;
    // Whether calls may pass any number of arguments: functions.inc's
    // `function { internal(N) }` take x, y, z plus their own parameters.
    bool variadic = false;
    // Set for kinds of function body not built yet (pattern, pigment,
    // transform, spline functions): declaring one is fine, using it stops
    // with `not supported yet: <unsupported>`.
    std::string unsupported;
};

}  // namespace frameray::sdl

// The built-in functions that functions.inc declares as
// `function { internal(N) }`: f_sphere, f_torus, f_noise3d and the rest.
// Each takes x, y, z and a fixed number of extra parameters. The formulas
// are matched against povray 3.7's values (probed with #debug, see
// tests/unit/internal_functions_test.cpp).
#pragma once

#include <memory>
#include <string>

#include "scene/noise.h"
#include "util/function_vm.h"

namespace frameray::scene {

struct InternalFunction {
    std::string name;  // functions.inc's name, e.g. "f_sphere"
    int extraParams = 0;
    // Null when frameray does not implement this one yet.
    std::shared_ptr<const NativeFunction> function;
};

// The internal function number n; nullopt-like (empty name) when povray
// has no function of that number.
// f_noise3d follows global_settings' noise_generator (measured), given as
// `noise`.
InternalFunction internalFunction(int n, NoiseGenerator noise = NoiseGenerator::RangeCorrected);

}  // namespace frameray::scene

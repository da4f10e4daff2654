// The built-in float functions of one and two arguments, as data shared
// by parse-time expressions and compiled user functions.
#pragma once

#include "sdl/keywords.h"

namespace frameray::sdl {

using UnaryFloatFunction = double (*)(double);
using BinaryFloatFunction = double (*)(double, double);

// nullptr when `kw` is not such a function.
UnaryFloatFunction unaryFloatFunction(Keyword kw);
BinaryFloatFunction binaryFloatFunction(Keyword kw);

}  // namespace frameray::sdl

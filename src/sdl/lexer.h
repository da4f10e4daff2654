// Turns scene-file text into tokens: words (keywords and identifiers),
// numbers, strings with their escapes decoded, symbols. Comments (`//` and
// nested `/* */`) are skipped. Errors throw SdlError with the position.
#pragma once

#include <memory>

#include "sdl/token.h"

namespace frameray::sdl {

std::shared_ptr<const TokenizedFile> tokenize(std::shared_ptr<const SourceFile> source);

}  // namespace frameray::sdl

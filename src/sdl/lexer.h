// Turns scene-file text into tokens: words (keywords and identifiers),
// numbers, strings with their escapes decoded, symbols. Comments (`//` and
// nested `/* */`) are skipped. Errors throw SdlError with the position.
#pragma once

#include <memory>

#include "sdl/token.h"

namespace frameray::sdl {

// Files of `compactFrom` bytes or more keep only some of their tokens
// (TokenizedFile::kCompactFrom; tests pass a smaller size).
std::shared_ptr<const TokenizedFile> tokenize(std::shared_ptr<const SourceFile> source,
                                              size_t compactFrom = TokenizedFile::kCompactFrom);

}  // namespace frameray::sdl

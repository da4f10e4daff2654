// The reserved words of the scene language as an enum generated from the
// data table keywords.def, with lookup by spelling.
#pragma once

#include <cstdint>
#include <string_view>

namespace frameray::sdl {

enum class Keyword : uint16_t {
    None = 0,  // not a reserved word: an identifier
#define KEYWORD(name) kw_##name,
#include "sdl/keywords.def"
#undef KEYWORD
    Count
};

// Returns Keyword::None when `word` is not reserved.
Keyword lookupKeyword(std::string_view word);
std::string_view keywordName(Keyword kw);

// The keywords that start a colour (`rgb`, `color`, `red`, `filter`, ...).
bool isColorKeyword(Keyword kw);

}  // namespace frameray::sdl

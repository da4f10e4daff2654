#include "sdl/keywords.h"

#include <algorithm>
#include <array>

namespace frameray::sdl {
namespace {

constexpr std::array<std::string_view, static_cast<size_t>(Keyword::Count)> kNames = {
    "",
#define KEYWORD(name) #name,
#include "sdl/keywords.def"
#undef KEYWORD
};

// keywords.def is sorted, so the names after the empty slot 0 are too.
static_assert(std::is_sorted(kNames.begin() + 1, kNames.end()), "keywords.def must stay sorted");

}  // namespace

Keyword lookupKeyword(std::string_view word) {
    auto it = std::lower_bound(kNames.begin() + 1, kNames.end(), word);
    if (it == kNames.end() || *it != word) return Keyword::None;
    return static_cast<Keyword>(it - kNames.begin());
}

std::string_view keywordName(Keyword kw) {
    return kNames[static_cast<size_t>(kw)];
}

bool isColorKeyword(Keyword kw) {
    constexpr Keyword kColorKeywords[] = {
        Keyword::kw_color, Keyword::kw_colour, Keyword::kw_rgb,      Keyword::kw_rgbf,
        Keyword::kw_rgbt,  Keyword::kw_rgbft,  Keyword::kw_srgb,     Keyword::kw_srgbf,
        Keyword::kw_srgbt, Keyword::kw_srgbft, Keyword::kw_red,      Keyword::kw_green,
        Keyword::kw_blue,  Keyword::kw_filter, Keyword::kw_transmit,
    };
    return std::find(std::begin(kColorKeywords), std::end(kColorKeywords), kw) !=
           std::end(kColorKeywords);
}

}  // namespace frameray::sdl

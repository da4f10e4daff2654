// "Did you mean" support: how far apart two spellings are, and the
// likeliest intended word among candidates.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace frameray::util {

// Edit distance between two words counting insertions, deletions,
// substitutions and swaps of neighbours (each 1). With `ignoreCase`,
// letters differing only in case are equal (INI keys); otherwise case
// counts (scene identifiers).
size_t spellingDistance(std::string_view a, std::string_view b, bool ignoreCase = false);

// The candidate closest to `word` when it is close enough to be a likely
// misspelling (words of 3 characters or more, at most one edit in 4
// characters, at least one allowed); empty when none is. Ties go to the
// first candidate in order.
std::string closestSpelling(std::string_view word, const std::vector<std::string_view>& candidates,
                            bool ignoreCase = false);

}  // namespace frameray::util

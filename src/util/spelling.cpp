#include "util/spelling.h"

#include <algorithm>
#include <cctype>

namespace frameray::util {

size_t spellingDistance(std::string_view a, std::string_view b, bool ignoreCase) {
    auto same = [ignoreCase](char x, char y) {
        if (!ignoreCase) return x == y;
        return std::tolower(static_cast<unsigned char>(x)) ==
               std::tolower(static_cast<unsigned char>(y));
    };
    // Three rows of the optimal-string-alignment table.
    std::vector<size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t cost = same(a[i - 1], b[j - 1]) ? 0 : 1;
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
                current[j] = std::min(current[j], before[j - 2] + 1);
        }
        std::swap(before, previous);
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::string closestSpelling(std::string_view word, const std::vector<std::string_view>& candidates,
                            bool ignoreCase) {
    if (word.size() < 3) return {};
    const size_t allowed = std::max<size_t>(1, word.size() / 4);
    std::string_view best;
    size_t bestDistance = allowed + 1;
    for (std::string_view c : candidates) {
        if (c == word || c.empty()) continue;
        // Cheap bound first: the length difference alone is that many edits.
        const size_t lengthGap =
            c.size() > word.size() ? c.size() - word.size() : word.size() - c.size();
        if (lengthGap >= bestDistance) continue;
        const size_t d = spellingDistance(word, c, ignoreCase);
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    return std::string(best);
}

}  // namespace frameray::util

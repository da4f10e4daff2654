// What makes a scene error easy to act on besides its position: a likely
// intended spelling of an unknown word, and the includes and macro calls
// that led to the error.
#include <fmt/format.h>

#include <algorithm>

#include "sdl/reader.h"

namespace frameray::sdl {

std::string Reader::withSpellingSuggestion(const Token& at, const std::string& message) const {
    if (at.kind != TokenKind::Word || at.kw != Keyword::None || lookup(at.text)) return message;
    if (message.find(fmt::format("'{}'", at.text)) == std::string::npos) return message;
    // Declared identifiers first (sorted, so ties do not depend on hash
    // order), then the reserved words.
    std::vector<std::string_view> names = symbols_.names();
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    // Reserved words are all lower case; a word with capitals is meant as
    // an identifier ('Offset' is not a misspelled 'offset').
    const bool lowerCase =
        std::none_of(at.text.begin(), at.text.end(), [](char c) { return c >= 'A' && c <= 'Z'; });
    if (lowerCase)
        for (size_t k = 1; k < static_cast<size_t>(Keyword::Count); ++k)
            names.push_back(keywordName(static_cast<Keyword>(k)));
    const std::string best = closestSpelling(at.text, names);
    if (best.empty()) return message;
    return fmt::format("{}; did you mean '{}'?", message, best);
}

std::vector<std::string> Reader::includeChain(const SourceLoc& at) const {
    // The innermost cursor reading the error's file; an error placed
    // elsewhere (a block's opening line) has no chain.
    size_t i = cursors_.size();
    while (i > 0 && cursors_[i - 1].file->source.get() != at.file) --i;
    std::vector<std::string> notes;
    for (; i > 1; --i) {
        const Cursor& c = cursors_[i - 1];
        if (!c.callSite.file) break;
        const std::string where =
            fmt::format("{}:{}:{}", c.callSite.file->path(), c.callSite.line, c.callSite.column);
        if (c.kind == CursorKind::Macro)
            notes.push_back(fmt::format("in macro '{}' called from {}", c.macroName, where));
        else
            notes.push_back(fmt::format("in file included from {}", where));
    }
    return notes;
}

}  // namespace frameray::sdl

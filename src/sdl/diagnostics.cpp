#include "sdl/diagnostics.h"

#include <fmt/format.h>

namespace frameray::sdl {

std::string formatDiagnostic(Severity severity, const SourceLoc& loc, const std::string& message) {
    const char* kind = severity == Severity::Error ? "error" : "warning";
    if (!loc.file) return fmt::format("{}: {}", kind, message);
    std::string out =
        fmt::format("{}:{}:{}: {}: {}", loc.file->path(), loc.line, loc.column, kind, message);
    std::string_view line = loc.file->lineText(static_cast<int>(loc.line));
    if (!line.empty()) {
        // A long line (a whole scene on one line, 10 MB of it) is quoted
        // only around the column: kSourceContext characters on each side.
        size_t column = loc.column > 0 ? loc.column - 1 : 0;
        std::string before, after;
        if (column > kSourceContext) {
            line.remove_prefix(column - kSourceContext);
            column = kSourceContext;
            before = "...";
        }
        if (line.size() > column + kSourceContext) {
            line = line.substr(0, column + kSourceContext);
            after = "...";
        }
        const std::string number = std::to_string(loc.line);
        out += fmt::format("\n {} | {}{}{}\n {} | {}", number, before, line, after,
                           std::string(number.size(), ' '), std::string(before.size(), ' '));
        // Keep tabs so the caret lines up under tab-indented source.
        for (size_t i = 0; i < column && i < line.size(); ++i) out += line[i] == '\t' ? '\t' : ' ';
        out += '^';
    }
    return out;
}

std::string formatNotes(const std::vector<std::string>& notes) {
    std::string out;
    for (const std::string& note : notes) out += "\nnote: " + note;
    return out;
}

}  // namespace frameray::sdl

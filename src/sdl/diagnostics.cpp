#include "sdl/diagnostics.h"

#include <fmt/format.h>

namespace frameray::sdl {

std::string formatDiagnostic(Severity severity, const SourceLoc& loc, const std::string& message) {
    const char* kind = severity == Severity::Error ? "error" : "warning";
    if (!loc.file) return fmt::format("{}: {}", kind, message);
    std::string out =
        fmt::format("{}:{}:{}: {}: {}", loc.file->path(), loc.line, loc.column, kind, message);
    const std::string_view line = loc.file->lineText(static_cast<int>(loc.line));
    if (!line.empty()) {
        const std::string number = std::to_string(loc.line);
        out += fmt::format("\n {} | {}\n {} | ", number, line, std::string(number.size(), ' '));
        // Keep tabs so the caret lines up under tab-indented source.
        for (uint32_t i = 0; i + 1 < loc.column && i < line.size(); ++i)
            out += line[i] == '\t' ? '\t' : ' ';
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

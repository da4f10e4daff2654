// Compiler-style diagnostics for scene files: "file:line:col: error: ...",
// the source line, a caret under the column, then notes (the include and
// macro chain that led there); and "did you mean" spelling suggestions.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "sdl/source.h"
#include "util/spelling.h"

namespace frameray::sdl {

enum class Severity { Warning, Error };

// Formats one diagnostic with its source line and caret (no trailing
// newline). A location without a file prints the message alone. Of a long
// source line only kSourceContext characters either side of the column
// are quoted, with "..." where it is cut.
inline constexpr size_t kSourceContext = 100;
std::string formatDiagnostic(Severity severity, const SourceLoc& loc, const std::string& message);

// "note: in file included from a.pov:3:2" style lines, one per element.
std::string formatNotes(const std::vector<std::string>& notes);

// Thrown for any error in a scene file; what() is the full formatted
// diagnostic followed by its notes. One error ends the frame's parse.
// The error keeps its source file alive: a lexer error in an include file
// unwinds past the last owner of that file, and the location is read again
// when the include chain is added.
class SdlError : public std::runtime_error {
  public:
    SdlError(const SourceLoc& loc, const std::string& message, std::vector<std::string> notes = {})
        : std::runtime_error(formatDiagnostic(Severity::Error, loc, message) + formatNotes(notes)),
          loc_(loc),
          file_(loc.file ? loc.file->weak_from_this().lock() : nullptr),
          message_(message),
          notes_(std::move(notes)) {}

    const SourceLoc& loc() const { return loc_; }
    const std::string& message() const { return message_; }
    const std::vector<std::string>& notes() const { return notes_; }

  private:
    SourceLoc loc_;
    std::shared_ptr<const SourceFile> file_;
    std::string message_;
    std::vector<std::string> notes_;
};

// Spelling suggestions come from util/spelling.h.
using util::closestSpelling;
using util::spellingDistance;

}  // namespace frameray::sdl

// Compiler-style diagnostics for scene files: "file:line:col: error: ...",
// the source line, and a caret under the column.
#pragma once

#include <stdexcept>
#include <string>

#include "sdl/source.h"

namespace frameray::sdl {

enum class Severity { Warning, Error };

// Formats one diagnostic with its source line and caret (no trailing
// newline). A location without a file prints the message alone.
std::string formatDiagnostic(Severity severity, const SourceLoc& loc, const std::string& message);

// Thrown for any error in a scene file; what() is the full formatted
// diagnostic. One error ends the frame's parse.
class SdlError : public std::runtime_error {
public:
    SdlError(const SourceLoc& loc, const std::string& message)
        : std::runtime_error(formatDiagnostic(Severity::Error, loc, message)),
          loc_(loc),
          message_(message) {}

    const SourceLoc& loc() const { return loc_; }
    const std::string& message() const { return message_; }

private:
    SourceLoc loc_;
    std::string message_;
};

}  // namespace frameray::sdl

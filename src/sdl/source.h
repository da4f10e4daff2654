// Source files as the lexer sees them, and positions inside them.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace frameray::sdl {

// The full text of one scene, include or macro file. Held by shared_ptr
// (tokens point into it); an SdlError keeps its file alive through
// weak_from_this, since the error may outlive the tokens of a failed include.
class SourceFile : public std::enable_shared_from_this<SourceFile> {
  public:
    SourceFile(std::string path, std::string text);

    const std::string& path() const { return path_; }
    const std::string& text() const { return text_; }
    // Text of line `line` (1-based) without its line terminator.
    std::string_view lineText(int line) const;

  private:
    std::string path_;
    std::string text_;
    std::vector<uint32_t> lineStarts_;
};

// A position in a source file, 1-based line and column, as compilers print.
struct SourceLoc {
    const SourceFile* file = nullptr;
    uint32_t line = 0;
    uint32_t column = 0;
};

}  // namespace frameray::sdl

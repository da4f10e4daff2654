#include "sdl/source.h"

namespace frameray::sdl {

SourceFile::SourceFile(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)) {
    lineStarts_.push_back(0);
    for (uint32_t i = 0; i < text_.size(); ++i) {
        // A lone CR (old Mac files) ends a line as well as LF or CRLF.
        if (text_[i] == '\n' || (text_[i] == '\r' && (i + 1 >= text_.size() || text_[i + 1] != '\n')))
            lineStarts_.push_back(i + 1);
    }
}

std::string_view SourceFile::lineText(int line) const {
    if (line < 1 || static_cast<size_t>(line) > lineStarts_.size()) return {};
    const uint32_t begin = lineStarts_[line - 1];
    uint32_t end = static_cast<size_t>(line) < lineStarts_.size() ? lineStarts_[line]
                                                                  : static_cast<uint32_t>(text_.size());
    while (end > begin && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) --end;
    return std::string_view(text_).substr(begin, end - begin);
}

}  // namespace frameray::sdl

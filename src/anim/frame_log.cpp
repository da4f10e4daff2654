#include "anim/frame_log.h"

#include <cstdio>
#include <fstream>

namespace frameray::anim {

void FrameLog::message(sdl::Stream stream, const std::string& text) {
    // #debug text is written as given (the scene supplies its own "\n");
    // every other message is a line of its own.
    std::string line = text;
    if (stream != sdl::Stream::Debug && (line.empty() || line.back() != '\n')) line += '\n';
    text_ += line;
    if (echo_ || stream == sdl::Stream::Fatal) {
        std::fputs(line.c_str(), stderr);
        std::fflush(stderr);
    }
}

void FrameLog::save(const std::filesystem::path& path) const {
    if (text_.empty()) return;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text_;
}

}  // namespace frameray::anim

#include "anim/frame_log.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "util/durable_file.h"

namespace frameray::anim {

using options::TextStream;

RunStreams::RunStreams(const options::RenderOptions& o) {
    const auto& all = o.streams[static_cast<int>(TextStream::All)];
    for (int i = 0; i < options::kTextStreams; ++i) {
        streams_[i].console =
            o.streams[i].console && (i == static_cast<int>(TextStream::All) || all.console);
        // Why a render failed always reaches the console: with -GA or -GF
        // povray still prints its fatal line, and a silent non-zero exit
        // leaves the user nothing to go on.
        if (i == static_cast<int>(TextStream::Fatal)) streams_[i].console = true;
        if (o.streams[i].file.empty()) continue;
        // Never through a link planted under the stream file's name.
        // Append_File (+GP): povray appends to the stream files then.
        const int fd = util::createNoFollow(o.streams[i].file, o.appendFile);
        streams_[i].file = ::fdopen(fd, o.appendFile ? "a" : "w");
        if (!streams_[i].file) {
            ::close(fd);
            throw std::runtime_error(
                fmt::format("cannot create stream file '{}'", o.streams[i].file));
        }
    }
}

RunStreams::~RunStreams() {
    for (auto& s : streams_)
        if (s.file) std::fclose(s.file);
}

bool RunStreams::console(TextStream stream) const {
    return streams_[static_cast<int>(stream)].console;
}

void RunStreams::setOverlay(ConsoleOverlay* overlay) {
    std::lock_guard lock(mutex_);
    overlay_ = overlay;
}

void RunStreams::write(TextStream stream, const std::string& text) {
    std::lock_guard lock(mutex_);
    const Stream& s = streams_[static_cast<int>(stream)];
    if (s.console) {
        if (overlay_) overlay_->hide();
        std::fputs(text.c_str(), stderr);
        std::fflush(stderr);
        if (overlay_) overlay_->show();
    }
    if (s.file) {
        std::fputs(text.c_str(), s.file);
        std::fflush(s.file);
    }
    if (std::FILE* all = streams_[static_cast<int>(TextStream::All)].file) {
        std::fputs(text.c_str(), all);
        std::fflush(all);
    }
}

TextStream toTextStream(sdl::Stream s) {
    switch (s) {
        case sdl::Stream::Debug:
            return TextStream::Debug;
        case sdl::Stream::Warning:
            return TextStream::Warning;
        case sdl::Stream::Render:
            return TextStream::Render;
        case sdl::Stream::Statistics:
            return TextStream::Statistic;
        case sdl::Stream::Fatal:
            return TextStream::Fatal;
    }
    return TextStream::Debug;
}

void FrameLog::message(sdl::Stream stream, const std::string& text) {
    // #debug text is written as given (the scene supplies its own "\n");
    // every other message is a line of its own.
    std::string line = text;
    if (stream != sdl::Stream::Debug && (line.empty() || line.back() != '\n')) line += '\n';
    message(toTextStream(stream), line);
}

void FrameLog::message(TextStream stream, const std::string& text) {
    std::lock_guard lock(mutex_);
    text_ += text;
    if (live_)
        streams_.write(stream, text);
    else
        held_.emplace_back(stream, text);
}

void FrameLog::goLive() {
    std::lock_guard lock(mutex_);
    if (live_) return;
    for (const auto& [stream, text] : held_) streams_.write(stream, text);
    held_.clear();
    live_ = true;
}

std::string FrameLog::text() const {
    std::lock_guard lock(mutex_);
    return text_;
}

void FrameLog::save(const std::filesystem::path& path) const {
    std::lock_guard lock(mutex_);
    if (text_.empty()) return;
    // Replaced, not rewritten in place: a symbolic link planted under the
    // log's name is replaced by the log, not followed.
    util::replaceFileDurably(path, text_);
}

}  // namespace frameray::anim

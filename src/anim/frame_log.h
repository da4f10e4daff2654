// Where a run's text goes. POV-Ray's six streams (debug, fatal, render,
// statistic, warning, and "all") each go to the console unless their
// *_Console option is off, and to a file when their *_File option names
// one - that file is created once per run and collects every frame, as
// povray does. On top of that every frame keeps its own log, beside its
// image, with all its messages in order.
#pragma once

#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>

#include "options/render_options.h"
#include "sdl/frame_context.h"

namespace frameray::anim {

class RunStreams {
public:
    // Opens (truncates) the stream files the options name. Throws
    // std::runtime_error when one cannot be created.
    explicit RunStreams(const options::RenderOptions& options);
    ~RunStreams();
    RunStreams(const RunStreams&) = delete;
    RunStreams& operator=(const RunStreams&) = delete;

    // `text` is written as given; callers supply line ends.
    void write(options::TextStream stream, const std::string& text);

private:
    struct Stream {
        bool console = true;
        std::FILE* file = nullptr;
    };
    std::array<Stream, options::kTextStreams> streams_;
    std::mutex mutex_;
};

options::TextStream toTextStream(sdl::Stream s);

class FrameLog final : public sdl::MessageSink {
public:
    explicit FrameLog(RunStreams& streams) : streams_(streams) {}

    void message(sdl::Stream stream, const std::string& text) override;
    void message(options::TextStream stream, const std::string& text);
    // Writes everything logged so far; an empty log writes no file.
    void save(const std::filesystem::path& path) const;
    const std::string& text() const { return text_; }

private:
    RunStreams& streams_;
    std::string text_;
};

}  // namespace frameray::anim

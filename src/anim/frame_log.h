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
#include <utility>
#include <vector>

#include "options/render_options.h"
#include "sdl/frame_context.h"

namespace frameray::anim {

// Something drawn on the console that other text must not land inside
// (the progress line on a terminal).
class ConsoleOverlay {
  public:
    virtual ~ConsoleOverlay() = default;
    virtual void hide() = 0;
    virtual void show() = 0;
};

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
    // Whether `stream` goes to the console.
    bool console(options::TextStream stream) const;
    // Hidden before and shown after every console write; null: none.
    void setOverlay(ConsoleOverlay* overlay);

  private:
    struct Stream {
        bool console = true;
        std::FILE* file = nullptr;
    };
    std::array<Stream, options::kTextStreams> streams_;
    std::mutex mutex_;
    ConsoleOverlay* overlay_ = nullptr;
};

options::TextStream toTextStream(sdl::Stream s);

// A frame's messages. A log made held (`live` false) keeps its console and
// stream output back until goLive(): frames overlap in the scheduler, and
// the run prints each frame's messages only once every earlier frame's are
// out, so the console reads exactly as when frames run one after another.
class FrameLog final : public sdl::MessageSink {
  public:
    explicit FrameLog(RunStreams& streams, bool live = true) : streams_(streams), live_(live) {}

    void message(sdl::Stream stream, const std::string& text) override;
    void message(options::TextStream stream, const std::string& text);
    // Writes out what was held back, in order; later messages go straight
    // to the streams.
    void goLive();
    // Writes everything logged so far (on the device when it returns); an
    // empty log writes no file. Throws std::runtime_error when it cannot.
    void save(const std::filesystem::path& path) const;
    std::string text() const;

  private:
    RunStreams& streams_;
    mutable std::mutex mutex_;
    bool live_;
    std::string text_;
    std::vector<std::pair<options::TextStream, std::string>> held_;
};

}  // namespace frameray::anim

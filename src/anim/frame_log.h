// A frame's text streams (#debug, #warning, errors...): kept in order for
// the frame's own log file and echoed to the console as they arrive.
#pragma once

#include <filesystem>
#include <string>

#include "sdl/frame_context.h"

namespace frameray::anim {

class FrameLog final : public sdl::MessageSink {
public:
    explicit FrameLog(bool echo) : echo_(echo) {}

    void message(sdl::Stream stream, const std::string& text) override;
    // Writes everything logged so far; an empty log writes no file.
    void save(const std::filesystem::path& path) const;

private:
    bool echo_;
    std::string text_;
};

}  // namespace frameray::anim

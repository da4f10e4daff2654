// Parsing SDL text in unit tests: a scene parsed from a string, with the
// warnings collected, and the error message a bad text stops with.
#pragma once

#include <string>

#include "sdl/interpreter.h"

namespace frameray::test_support {

struct WarningSink : sdl::MessageSink {
    std::string warnings;
    void message(sdl::Stream s, const std::string& t) override {
        if (s == sdl::Stream::Warning) warnings += t;
    }
};

// Parses `text` as the file t.pov; throws what the parser throws.
struct ParsedScene {
    sdl::FrameContext ctx;
    sdl::TokenCache cache;
    WarningSink sink;
    sdl::Interpreter interp{ctx, cache, sink};
    scene::Scene scene;
    explicit ParsedScene(const std::string& text, sdl::FrameContext context = {})
        : ctx(std::move(context)) {
        scene = interp.parseText("t.pov", text);
    }
};

// The message parsing `text` stops with, or "" when it parses.
inline std::string parseErrorOf(const std::string& text, const sdl::FrameContext& context = {}) {
    try {
        ParsedScene p(text, context);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

}  // namespace frameray::test_support

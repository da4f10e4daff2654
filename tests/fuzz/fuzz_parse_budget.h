// What fuzz_scene and fuzz_render share: the frame every input is parsed
// for (standard includes, no file writes, small parse budgets) and a sink
// that drops the scene's messages.
//
// Budgets per input: the parse-iteration limit and smaller array and
// string limits bound the time and memory of one input; libFuzzer's
// -timeout and -rss_limit_mb (see run_fuzzers.sh) catch what they miss.
#pragma once

#include <cstddef>
#include <string>

#include "sdl/interpreter.h"

namespace frameray::fuzz {

inline sdl::FrameContext fuzzFrame() {
    sdl::FrameContext frame;
    frame.libraryPaths = {"/usr/share/povray-3.7/include"};
    // The fuzzer must not write files where it runs.
    frame.refuseFileWrites = "the fuzzer does not write files";
    frame.limits.parseIterations = 5'000;
    frame.limits.arrayElements = std::size_t(1) << 16;
    frame.limits.totalArrayElements = std::size_t(1) << 20;
    frame.limits.stringLength = std::size_t(1) << 20;
    return frame;
}

struct DiscardMessages : sdl::MessageSink {
    void message(sdl::Stream, const std::string&) override {}
};

}  // namespace frameray::fuzz

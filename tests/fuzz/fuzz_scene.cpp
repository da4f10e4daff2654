// libFuzzer target: the whole scene-language interpreter on arbitrary bytes
// parsed as a scene file (includes resolve against the standard povray
// include folder). Any input must either parse or end with an exception for
// its frame (SdlError, or std::bad_alloc reported as out of memory);
// crashes, sanitizer reports and hangs are bugs.
//
// Budgets per input: the parse-iteration limit and smaller array and
// string limits bound the time and memory of one input; libFuzzer's
// -timeout and -rss_limit_mb (see run_fuzzers.sh) catch what they miss.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "sdl/interpreter.h"

namespace {

struct DiscardMessages : frameray::sdl::MessageSink {
    void message(frameray::sdl::Stream, const std::string&) override {}
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace frameray::sdl;
    // Shared by the inputs like frames of one run share it: include files
    // are read and lexed once.
    static TokenCache cache;
    FrameContext frame;
    frame.libraryPaths = {"/usr/share/povray-3.7/include"};
    // The fuzzer must not write files where it runs.
    frame.refuseFileWrites = "the fuzzer does not write files";
    frame.limits.parseIterations = 5'000;
    frame.limits.arrayElements = size_t(1) << 16;
    frame.limits.totalArrayElements = size_t(1) << 20;
    frame.limits.stringLength = size_t(1) << 20;
    DiscardMessages messages;
    try {
        Interpreter interpreter(frame, cache, messages);
        const std::string text(reinterpret_cast<const char*>(data), size);
        (void)interpreter.parseText("fuzz.pov", text);
    } catch (const std::exception& e) {
        (void)e.what();
    }
    return 0;
}

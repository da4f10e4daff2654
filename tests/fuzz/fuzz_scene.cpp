// libFuzzer target: the whole scene-language interpreter on arbitrary bytes
// parsed as a scene file (includes resolve against the standard povray
// include folder). Any input must either parse or end with an exception for
// its frame (SdlError, or std::bad_alloc reported as out of memory);
// crashes, sanitizer reports and hangs are bugs.
//
// Budgets per input: see fuzz_parse_budget.h.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "fuzz_parse_budget.h"
#include "sdl/interpreter.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace frameray::sdl;
    // Shared by the inputs like frames of one run share it: include files
    // are read and lexed once.
    static TokenCache cache;
    FrameContext frame = frameray::fuzz::fuzzFrame();
    frameray::fuzz::DiscardMessages messages;
    try {
        Interpreter interpreter(frame, cache, messages);
        const std::string text(reinterpret_cast<const char*>(data), size);
        (void)interpreter.parseText("fuzz.pov", text);
    } catch (const std::exception& e) {
        (void)e.what();
    }
    return 0;
}

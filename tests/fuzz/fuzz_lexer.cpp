// libFuzzer target: the lexer on arbitrary bytes. Any input must either
// tokenize or throw SdlError (and formatting that error must work too);
// anything else - a crash, a sanitizer report, a hang - is a bug.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "sdl/diagnostics.h"
#include "sdl/lexer.h"
#include "sdl/source.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace frameray::sdl;
    auto source = std::make_shared<SourceFile>(
        "fuzz.pov", std::string(reinterpret_cast<const char*>(data), size));
    try {
        const auto tokens = tokenize(source);
        // Every token's location must be inside the file; a diagnostic
        // at the last one (formatting each would dominate the run time).
        size_t columns = 0;
        for (const Token& t : tokens->tokens)
            columns += source->lineText(static_cast<int>(t.line)).size();
        (void)columns;
        if (!tokens->tokens.empty())
            (void)formatDiagnostic(Severity::Warning, tokens->locOf(tokens->tokens.back()),
                                   "last token");
    } catch (const SdlError& e) {
        (void)e.what();
    }
    return 0;
}

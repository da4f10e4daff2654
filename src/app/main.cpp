// frameray: renders POV-Ray scenes and animations from INI files and
// switches. Wiring only: options -> sequence -> frame loop.
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "anim/frame_loop.h"
#include "anim/sequence.h"
#include "options/option_table.h"
#include "options/options.h"

int main(int argc, char** argv) {
    using namespace frameray;
    std::vector<std::string> args(argv + 1, argv + argc);
    for (const std::string& a : args)
        if (a == "--help" || a == "-h" || a == "-?") {
            std::fputs(options::helpText().c_str(), stdout);
            return 0;
        } else if (a == "--options-markdown") {
            std::fputs(options::optionsMarkdown().c_str(), stdout);
            return 0;
        }
    spdlog::set_pattern("%v");

    options::RenderOptions opts;
    anim::Sequence sequence;
    try {
        options::applyArguments(opts, args);
        if (opts.inputFile.empty()) throw options::OptionError("no scene file given (Input_File_Name or +I)");
        std::error_code ec;
        if (!std::filesystem::is_regular_file(opts.inputFile, ec))
            throw options::OptionError("cannot open scene file '" + opts.inputFile + "': no such file");
        // Options whose effect is not built yet must not be silently ignored.
        if (opts.antialias) throw options::OptionError("not supported yet: anti-aliasing (Antialias=on / +A)");
        if (opts.quality < 4)
            throw options::OptionError("not supported yet: Quality below 4 (+Q0..+Q3 drop shadows and shading)");
        sequence = anim::planSequence(opts);
    } catch (const options::OptionError& e) {
        std::fprintf(stderr, "frameray: error: %s\n", e.what());
        return 2;
    }

    std::unique_ptr<tbb::global_control> threads;
    if (opts.workThreads > 0)
        threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                        static_cast<size_t>(opts.workThreads));
    return anim::runSequence(opts, sequence);
}

// frameray: renders POV-Ray scenes and animations from INI files and
// switches. Wiring only: options -> sequence -> frame loop.
#include <tbb/global_control.h>

#include <csignal>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "anim/frame_loop.h"
#include "anim/interrupt.h"
#include "anim/sequence.h"
#include "anim/shard_statistics.h"
#include "app/version.h"
#include "options/option_table.h"
#include "options/options.h"
#include "util/durable_file.h"

int main(int argc, char** argv) {
    using namespace frameray;
    // First, before any thread exists: Ctrl-C is handled by a watcher.
    anim::installInterruptWatcher();
    // A write past `ulimit -f` would kill the process with SIGXFSZ and no
    // word; ignored, the write fails with EFBIG ("File too large") and the
    // frame ends with that message, as a full disk does.
    std::signal(SIGXFSZ, SIG_IGN);

    std::vector<std::string> args(argv + 1, argv + argc);
    // --list-frames: print the frames the options ask for (number, clock,
    // file) and stop, without checking that the scene can be rendered.
    bool listFrames = false;
    std::erase_if(args, [&](const std::string& a) {
        return a == "--list-frames" ? (listFrames = true) : false;
    });
    // --merge-stats DIR: one sequence.json for a sequence rendered in
    // shards, from their sequence.shard-I-of-N.json files in DIR.
    if (!args.empty() && args[0] == "--merge-stats") {
        if (args.size() != 2) {
            std::fputs(
                "frameray: error: --merge-stats takes one folder: frameray --merge-stats DIR\n",
                stderr);
            return 2;
        }
        try {
            const anim::MergedStatistics merged = anim::mergeShardStatisticsIn(args[1]);
            std::printf("%s: %zu shards, %zu frames rendered, %zu kept (+C)\n", merged.file.c_str(),
                        merged.shards, merged.framesRendered, merged.framesKept);
            return 0;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "frameray: error: --merge-stats: %s\n", e.what());
            return 2;
        }
    }
    for (const std::string& a : args)
        if (a == "--help" || a == "-h" || a == "-?") {
            std::fputs(options::helpText().c_str(), stdout);
            return 0;
        } else if (a == "--version" || a == "-version" || a == "--V") {  // povray's spellings
            std::fputs(app::versionText().c_str(), stdout);
            return 0;
        } else if (a == "--options-markdown") {
            std::fputs(options::optionsMarkdown().c_str(), stdout);
            return 0;
        }

    options::RenderOptions opts;
    anim::Sequence sequence;
    try {
        // POV-Ray's order: defaults, the startup sources, then the
        // arguments (switches, Key=Value and INI files) in order.
        std::vector<std::string> warnings =
            options::applyStartupOptions(opts, options::processEnvironment());
        for (const std::string& w : options::applyArguments(opts, args)) warnings.push_back(w);
        for (const std::string& w : warnings)
            std::fprintf(stderr, "frameray: warning: %s\n", w.c_str());
        opts.optionWarnings = std::move(warnings);
        if (opts.inputFile.empty())
            throw options::OptionError("no scene file given (Input_File_Name or +I)");
        if (!opts.createIni.empty()) {
            // Replaced, never written through a link planted under its name.
            try {
                util::replaceFileDurably(opts.createIni, options::createIniText(opts));
            } catch (const std::exception& e) {
                throw options::OptionError(std::string("Create_Ini: ") + e.what());
            }
        }
        if (listFrames) {
            const anim::Sequence planned = anim::planSequence(opts);
            for (const anim::FrameSpec& f : planned.frames)
                std::printf("%d %.17g %s\n", f.number, f.clock, f.output.c_str());
            return 0;
        }
        // As povray: the working folder, then the library path (+L).
        const std::filesystem::path scene = options::findSceneFile(opts);
        if (scene.empty())
            throw options::OptionError("cannot open scene file '" + opts.inputFile +
                                       "': no such file");
        opts.inputFile = scene.string();
        // Options whose effect is not built yet must not be silently
        // ignored; the option table says which values need what.
        if (const std::string missing = options::firstUnsupported(opts); !missing.empty())
            throw options::OptionError("not supported yet: " + missing);
        sequence = anim::planSequence(opts);
        anim::checkOutputFolder(opts, sequence);
    } catch (const options::OptionError& e) {
        std::fprintf(stderr, "frameray: error: %s\n", e.what());
        return 2;
    }

    // Frames are parsed on worker threads too: give them the stack the
    // interpreter's nesting limit assumes (sdl::FrameContext::Limits) with
    // room to spare, as the main thread has (TBB's default is 4 MB).
    const tbb::global_control stackSize(tbb::global_control::thread_stack_size, size_t(16) << 20);
    std::unique_ptr<tbb::global_control> threads;
    if (opts.workThreads > 0)
        threads = std::make_unique<tbb::global_control>(
            tbb::global_control::max_allowed_parallelism, static_cast<size_t>(opts.workThreads));
    return anim::runSequence(opts, sequence);
}

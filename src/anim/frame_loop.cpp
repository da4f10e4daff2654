#include "anim/frame_loop.h"

#include <fmt/format.h>
#include <signal.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <set>

#include "anim/frame_log.h"
#include "anim/hooks.h"
#include "anim/interrupt.h"
#include "anim/journal.h"
#include "image/image_io.h"
#include "options/option_table.h"
#include "render/gamma.h"
#include "render/renderer.h"
#include "render/world.h"
#include "sdl/diagnostics.h"
#include "sdl/interpreter.h"
#include "sdl/token_cache.h"

namespace frameray::anim {

namespace fs = std::filesystem;
using options::ShellHook;
using options::TextStream;

namespace {

const fs::path kDefaultLibrary = "/usr/share/povray-3.7/include";

sdl::FrameContext contextFor(const options::RenderOptions& o, const Sequence& seq, const FrameSpec& f) {
    sdl::FrameContext ctx;
    ctx.clock = f.clock;
    ctx.clockDelta = f.clockDelta;
    ctx.clockOn = seq.clockOn;
    ctx.frameNumber = f.number;
    ctx.initialClock = seq.initialClock;
    ctx.finalClock = seq.finalClock;
    ctx.initialFrame = seq.initialFrame;
    ctx.finalFrame = seq.finalFrame;
    ctx.imageWidth = o.width;
    ctx.imageHeight = o.height;
    ctx.libraryPaths = o.libraryPaths;
    // The standard include files stay reachable even without a povray.ini.
    if (std::find(ctx.libraryPaths.begin(), ctx.libraryPaths.end(), kDefaultLibrary) == ctx.libraryPaths.end())
        ctx.libraryPaths.push_back(kDefaultLibrary);
    ctx.declares = o.declares;
    ctx.version = o.version;
    return ctx;
}

image::EncodedImage encode(const render::FrameImage& img, const render::GammaEncoding& gamma, int bitDepth,
                           const RenderWindow& window) {
    image::EncodedImage out;
    out.width = img.width;
    out.height = img.height;
    out.channels = 3;
    out.bitDepth = bitDepth;
    out.values.resize(img.rgb.size());
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            // povray writes the pixels outside the render window black.
            const bool inside = x >= window.x0 && x < window.x1 && y >= window.y0 && y < window.y1;
            for (int c = 0; c < 3; ++c) {
                const size_t i = (static_cast<size_t>(y) * img.width + x) * 3 + c;
                out.values[i] = inside ? static_cast<float>(gamma.encode(img.rgb[i])) : 0.0f;
            }
        }
    return out;
}

// What makes two runs' images comparable: a journal written with other
// values is not trusted.
std::uint64_t settingsHash(const options::RenderOptions& o, const Sequence& seq) {
    std::error_code ec;
    std::string s = fmt::format("{}|{}x{}|{}{}|{}|{},{},{},{}|{}|{}|{}", fs::absolute(o.inputFile, ec).string(), o.width,
                                o.height, o.outputType, o.bitDepth, o.fileGamma, seq.window.x0, seq.window.y0,
                                seq.window.x1, seq.window.y1, o.version, o.quality, o.includeHeader);
    for (const auto& [k, v] : o.declares) s += fmt::format("|{}={}", k, v);
    for (const auto& p : o.libraryPaths) s += fmt::format("|{}", p.string());
    return hashText(s);
}

// Temporary files left by a run that was killed mid-write.
void removeStaleTemporaries(const Sequence& seq) {
    std::set<fs::path> folders;
    std::set<std::string> names;
    for (const FrameSpec& f : seq.frames) {
        folders.insert(f.output.parent_path().empty() ? fs::path(".") : f.output.parent_path());
        names.insert(f.output.filename().string());
    }
    for (const fs::path& dir : folders) {
        std::error_code ec;
        for (const auto& entry : fs::directory_iterator(dir, ec)) {
            const std::string name = entry.path().filename().string();
            if (name.empty() || name[0] != '.') continue;
            const auto dot = name.find(".", 1);
            if (dot == std::string::npos) continue;
            for (const std::string& target : names) {
                long pid = 0;
                if (!image::isTemporaryFor(name, target, pid)) continue;
                if (pid != static_cast<long>(getpid()) && kill(static_cast<pid_t>(pid), 0) == 0) continue;  // alive
                fs::remove(entry.path(), ec);
                break;
            }
        }
    }
}

class Run {
public:
    Run(const options::RenderOptions& o, const Sequence& seq) : o_(o), seq_(seq), streams_(o) {}
    ~Run() { setEmergencyStop(nullptr); }
    Run(const Run&) = delete;
    Run& operator=(const Run&) = delete;

    int execute() {
        if (o_.outputToFile && !seq_.frames.empty()) {
            std::error_code ec;
            for (const FrameSpec& f : seq_.frames)
                if (!f.output.parent_path().empty()) fs::create_directories(f.output.parent_path(), ec);
            if (!seq_.journal.parent_path().empty()) fs::create_directories(seq_.journal.parent_path(), ec);
            removeStaleTemporaries(seq_);
            journal_ = std::make_unique<Journal>(seq_.journal, settingsHash(o_, seq_), o_.continueTrace);
            if (journal_->discardedStale())
                say(TextStream::Warning, fmt::format("frameray: the journal {} was written with other settings; "
                                                     "rendering every frame again\n", seq_.journal.string()));
        }
        setEmergencyStop([this] { emergencyStop(); });

        HookValues scene = values(nullptr);
        switch (runHook(o_.commands[static_cast<int>(ShellHook::PreScene)], scene)) {
            case HookAction::Continue: break;
            case HookAction::SkipFrame: case HookAction::SkipAll: return finish();
            case HookAction::Quit: return 0;
            case HookAction::UserAbort: return userAbort();
            case HookAction::Fatal: return fatal("Pre_Scene_Command failed", nullptr);
        }

        for (const FrameSpec& frame : seq_.frames) {
            ++index_;
            if (stopRequested()) return userAbort();
            const std::string clock = clockText(frame.clock);
            if (o_.continueTrace && journal_ && journal_->verified(frame.number, clock, frame.output)) {
                ++finished_;
                if (o_.verbose)
                    say(TextStream::Render, fmt::format("frame {} ({} of {}): {} is finished already (Continue_Trace)\n",
                                                        frame.number, index_, seq_.frames.size(),
                                                        frame.output.string()));
                continue;
            }
            switch (runHook(o_.commands[static_cast<int>(ShellHook::PreFrame)], values(&frame))) {
                case HookAction::Continue: break;
                case HookAction::SkipFrame: continue;
                case HookAction::SkipAll: return finish();
                case HookAction::Quit: return 0;
                case HookAction::UserAbort: return userAbort();
                case HookAction::Fatal: return fatal("Pre_Frame_Command failed", &frame);
            }
            if (const int status = renderOne(frame); status != 0) return status;
            switch (runHook(o_.commands[static_cast<int>(ShellHook::PostFrame)], values(&frame))) {
                case HookAction::Continue: case HookAction::SkipFrame: break;
                case HookAction::SkipAll: return finish();
                case HookAction::Quit: return 0;
                case HookAction::UserAbort: return userAbort();
                case HookAction::Fatal: return fatal("Post_Frame_Command failed", &frame);
            }
        }
        return finish();
    }

private:
    int finish() {
        switch (runHook(o_.commands[static_cast<int>(ShellHook::PostScene)], values(nullptr))) {
            case HookAction::UserAbort: return userAbort();
            case HookAction::Fatal: return fatal("Post_Scene_Command failed", nullptr);
            default: return 0;
        }
    }

    HookValues values(const FrameSpec* frame) const {
        HookValues v;
        v.scene = seq_.sceneName;
        v.width = o_.width;
        v.height = o_.height;
        const FrameSpec& f = frame ? *frame : seq_.frames.front();
        v.output = f.output.string();
        v.frame = f.number;
        v.clock = f.clock;
        return v;
    }

    void say(TextStream stream, const std::string& text) { streams_.write(stream, text); }

    // Parses, renders and writes one frame. Returns 0, or the exit status.
    int renderOne(const FrameSpec& frame) {
        const auto start = std::chrono::steady_clock::now();
        FrameLog log(streams_);
        current_ = &frame;
        try {
            sdl::Interpreter interpreter(contextFor(o_, seq_, frame), cache_, log);
            const scene::Scene scene = interpreter.parseFile(o_.inputFile);
            if (stopRequested()) return userAbort();
            const render::World world(scene);
            render::FrameStats stats;
            const render::FrameImage image = render::renderFrame(world, {o_.width, o_.height}, stats);
            if (stopRequested()) return userAbort();
            if (o_.outputToFile) {
                const auto gamma = render::GammaEncoding::forScene(scene, o_.fileGamma);
                image::writeAtomic(frame.output, seq_.fileType, encode(image, gamma, o_.bitDepth, seq_.window));
                if (journal_) journal_->record(frame.number, clockText(frame.clock), frame.output);
            }
            ++finished_;
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const std::string where = o_.outputToFile ? frame.output.string() : std::string("(no file)");
            const std::string render = fmt::format("frame {} ({} of {}): {}\n", frame.number, index_,
                                                   seq_.frames.size(), where);
            const std::string statistic = fmt::format("frame {}: {:.2f} s, {} camera rays, {} shadow rays\n",
                                                      frame.number, seconds, stats.rays.camera, stats.rays.shadow);
            if (o_.verbose) {
                log.message(TextStream::Render, render);
                log.message(TextStream::Statistic, statistic);
            }
        } catch (const sdl::SdlError& e) {
            log.message(sdl::Stream::Fatal, e.what());
            if (o_.outputToFile) log.save(frame.log);
            return fatal("", &frame);
        } catch (const std::exception& e) {
            log.message(sdl::Stream::Fatal, fmt::format("error: frame {}: {}", frame.number, e.what()));
            if (o_.outputToFile) log.save(frame.log);
            return fatal("", &frame);
        }
        if (o_.outputToFile) log.save(frame.log);
        current_ = nullptr;
        return 0;
    }

    int fatal(const std::string& why, const FrameSpec* frame) {
        if (!why.empty()) say(TextStream::Fatal, fmt::format("frameray: error: {}\n", why));
        runHook(o_.commands[static_cast<int>(ShellHook::FatalError)], values(frame));
        return 1;
    }

    std::string stopMessage() const {
        return fmt::format("frameray: interrupted; {} of {} frames are finished{}\n", finished_.load(),
                           seq_.frames.size(),
                           journal_ ? " - run again with +C (Continue_Trace=on) to render the rest" : "");
    }

    int userAbort() {
        acknowledgeStop();
        say(TextStream::Fatal, stopMessage());
        runHook(o_.commands[static_cast<int>(ShellHook::UserAbort)], values(current_));
        return 2;
    }

    // Runs on the watcher thread while a frame is still rendering.
    void emergencyStop() {
        if (const FrameSpec* f = current_) {
            std::error_code ec;
            fs::remove(image::temporaryPathFor(f->output), ec);
        }
        std::fputs(stopMessage().c_str(), stderr);
        runHook(o_.commands[static_cast<int>(ShellHook::UserAbort)], values(current_));
    }

    const options::RenderOptions& o_;
    const Sequence& seq_;
    RunStreams streams_;
    sdl::TokenCache cache_;  // shared by the frames: files are lexed once
    std::unique_ptr<Journal> journal_;
    std::atomic<const FrameSpec*> current_{nullptr};
    size_t index_ = 0;
    std::atomic<size_t> finished_{0};
};

}  // namespace

int runSequence(const options::RenderOptions& o, const Sequence& seq) {
    try {
        Run run(o, seq);
        return run.execute();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "frameray: error: %s\n", e.what());
        return 1;
    }
}

}  // namespace frameray::anim

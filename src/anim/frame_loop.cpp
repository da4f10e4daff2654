#include "anim/frame_loop.h"

#include <fmt/format.h>
#include <signal.h>
#include <sys/resource.h>
#include <tbb/global_control.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_group.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <deque>
#include <fstream>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <optional>
#include <set>
#include <thread>
#include <vector>

#include "anim/contact_sheet.h"
#include "anim/frame_log.h"
#include "anim/hooks.h"
#include "anim/interrupt.h"
#include "anim/journal.h"
#include "anim/memory_budget.h"
#include "anim/preview_video.h"
#include "anim/progress.h"
#include "anim/run_log.h"
#include "anim/shard_statistics.h"
#include "anim/statistics.h"
#include "image/codecs.h"
#include "image/frame_encoding.h"
#include "image/image_io.h"
#include "options/option_table.h"
#include "render/aov_pass.h"
#include "render/radiosity_file.h"
#include "render/renderer.h"
#include "render/world.h"
#include "sdl/diagnostics.h"
#include "sdl/interpreter.h"
#include "sdl/token_cache.h"
#include "util/durable_file.h"

namespace frameray::anim {

namespace fs = std::filesystem;
using options::LogLevel;
using options::ShellHook;
using options::TextStream;

namespace {

const fs::path kDefaultLibrary = options::kStandardIncludeFolder;

sdl::FrameContext contextFor(const options::RenderOptions& o, const Sequence& seq,
                             const FrameSpec& f) {
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
    if (std::find(ctx.libraryPaths.begin(), ctx.libraryPaths.end(), kDefaultLibrary) ==
        ctx.libraryPaths.end())
        ctx.libraryPaths.push_back(kDefaultLibrary);
    ctx.declares = o.declares;
    ctx.includeHeader = o.includeHeader;
    ctx.version = o.version;
    ctx.versionGiven = o.versionGiven;
    if (o.fileRestrictions) {
        sdl::FileAccessFolders folders;
        std::error_code ec;
        folders.working = fs::current_path(ec);
        folders.scene = fs::absolute(o.inputFile, ec).parent_path();
        folders.output = f.output.parent_path().empty() ? folders.working : f.output.parent_path();
        folders.library = ctx.libraryPaths;
        folders.extraRead = o.readPaths;
        folders.extraWrite = o.writePaths;
        ctx.fileAccess = sdl::FileAccessPolicy::restrictedTo(folders);
    }
    ctx.limits.parseIterations = static_cast<size_t>(o.maxParseIterations);
    if (seq.shardCount > 1)
        ctx.refuseFileWrites = fmt::format(
            "frames that pass state through files must be rendered in order by one process, so "
            "this scene "
            "cannot be split into shards (Shard_Count {}); render it without Shard_Count / +SHC",
            seq.shardCount);
    return ctx;
}

render::AovRequest aovRequest(const options::RenderOptions& o) {
    render::AovRequest r;
    for (const std::string& name : o.outputAovs) {
        r.depth |= name == "depth";
        r.normal |= name == "normal";
        r.objectId |= name == "object_id";
        r.albedo |= name == "albedo";
    }
    return r;
}

// What alpha output (+UA) does not handle yet: rainbows' transmittance is
// not measured.
void refuseAlphaWith(const scene::Scene& scene) {
    if (!scene.atmosphere.rainbows.empty())
        throw std::runtime_error("not supported yet: alpha output (+UA) with a rainbow");
}

// Options that do not change what a frame looks like: which frames a run
// renders (subsets, steps, shards), how it runs, and where its messages go.
// Every other option is part of the journal's settings hash.
bool settingsNeutral(std::string_view key) {
    // clang-format off
    static constexpr std::string_view kNeutral[] = {
        "Allow_Shell_Commands", "Bounding",           "Bounding_Threshold", "Contact_Sheet",
        "Continue_Trace",       "Preview_Fps",        "Preview_Video",
        "Create_Ini",           "Display",            "Display_Gamma",      "Field_Render",
        "File_Restrictions",    "Frame_Step",         "Frames_In_Flight",   "Input_File_Name",
        "Log_Format",           "Log_Level",
        "Max_Parse_Iterations", "Odd_Field",          "Output_File_Name",   "Output_To_File",
        "Pause_When_Done",      "Read_Path",          "Shard_Count",        "Shard_Index",
        "Subset_End_Frame",     "Subset_Start_Frame", "Test_Abort",         "Test_Abort_Count",
        "Verbose",              "Work_Threads",       "Write_Path"};
    // clang-format on
    for (const std::string_view n : kNeutral)
        if (key == n) return true;
    // The text streams and the shell-outs.
    return key.ends_with("_Console") || key.ends_with("_File") || key.ends_with("_Command") ||
           key.ends_with("_Return");
}

// What makes two runs' images comparable: a journal written with other
// values of any option that changes a frame (size, window, quality,
// anti-aliasing, gamma, clocks, declares, library path...) is not trusted.
// The scene and the files it reads are checked frame by frame (journal.h).
std::uint64_t settingsHash(const options::RenderOptions& o) {
    std::error_code ec;
    std::string s = fs::absolute(o.inputFile, ec).string();
    for (const options::OptionSpec& spec : options::optionTable()) {
        if (settingsNeutral(spec.iniKey)) continue;
        s += fmt::format("|{}", spec.iniKey);
        for (const std::string& value : options::optionValues(spec, o)) s += "=" + value;
    }
    return hashText(s);
}

// The journals of a sharded run of this sequence (beside its own), which a
// run without shards takes over when resuming.
std::vector<fs::path> shardJournals(const Sequence& seq) {
    std::vector<fs::path> out;
    if (seq.shardCount > 1) return out;
    const std::string name = seq.journal.filename().string();  // ".NAME.frameray-journal"
    const std::string suffix = ".frameray-journal";
    if (!name.ends_with(suffix)) return out;
    const std::string prefix = name.substr(0, name.size() - suffix.size()) + ".shard-";
    const fs::path dir =
        seq.journal.parent_path().empty() ? fs::path(".") : seq.journal.parent_path();
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string n = entry.path().filename().string();
        if (n.starts_with(prefix) && n.ends_with(suffix)) out.push_back(entry.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// A file as the journal names it: absolute, '..' and links resolved.
std::string journalName(const fs::path& p) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(p, ec);
    const fs::path canonical = fs::weakly_canonical(absolute, ec);
    return (ec ? absolute.lexically_normal() : canonical).string();
}

// Temporary files left by a run that was killed mid-write: of the frames,
// their logs, sequence.json and the journal (rewritten when a run resumes).
void removeStaleTemporaries(const Sequence& seq) {
    // Every frame of a sequence is in one folder; the journal beside them.
    std::set<fs::path> folders;
    const fs::path frameFolder = seq.frames.front().output.parent_path();
    folders.insert(frameFolder.empty() ? fs::path(".") : frameFolder);
    std::set<std::string> names{seq.statisticsName};
    const fs::path imageExtension = seq.frames.front().output.extension();
    if (!seq.journal.empty()) {
        folders.insert(seq.journal.parent_path().empty() ? fs::path(".")
                                                         : seq.journal.parent_path());
        names.insert(seq.journal.filename().string());
    }
    for (const fs::path& dir : folders) {
        std::error_code ec;
        for (const auto& entry : fs::directory_iterator(dir, ec)) {
            const std::string name = entry.path().filename().string();
            long pid = 0;
            std::string target;
            if (!image::parseTemporaryName(name, target, pid)) continue;
            // A frame's log (NAME.log beside NAME.png) is replaced too.
            const bool log = target.ends_with(".log") &&
                             seq.frames.holdsImageNamed(
                                 fs::path(target).replace_extension(imageExtension).string());
            if (!names.count(target) && !seq.frames.holdsImageNamed(target) && !log) continue;
            if (pid != static_cast<long>(getpid()) && kill(static_cast<pid_t>(pid), 0) == 0)
                continue;  // alive
            fs::remove(entry.path(), ec);
        }
    }
}

// A frame's way through the pipeline, or a marker that ends the run once
// every earlier frame is out.
struct Outcome {
    enum class Kind { None, Finish, Quit, UserAbort, Fatal };
    Kind kind = Kind::None;
    std::string why;  // Fatal: the message ("" when the frame's log has it)
    const FrameSpec* frame = nullptr;
};

struct Job {
    enum class Kind { Render, Kept, Stop };
    Kind kind = Kind::Render;
    size_t index = 0;     // position in the pipeline (order of stage 3)
    size_t position = 0;  // position in the sequence
    const FrameSpec* frame = nullptr;
    Outcome stop;    // Kind::Stop
    FrameSpec spec;  // what `frame` points to
    // What the frame's parse read (with the files' hashes) and wrote, for
    // the journal.
    FrameInputs inputs;
    std::vector<std::string> written;
    std::unique_ptr<FrameLog> log;
    std::unique_ptr<sdl::Interpreter> interpreter;  // kept while the scene lives
    std::optional<scene::Scene> scene;
    // The image encoded and flushed under a temporary name in stage 2;
    // stage 3 renames it into place and journals it.
    fs::path temporary;
    // +O-: the encoded image, written to standard output in stage 3.
    std::vector<unsigned char> encoded;
    std::uintmax_t fileSize = 0;
    std::uint64_t fileHash = 0;
    render::FrameStats stats;
    render::ShapeTestCounts shapeTests;
    // The frame's radiosity samples, for Radiosity_To_File (stage 3).
    std::vector<render::RadiositySample> radiosityCache;
    Rgb8Image thumbnail;  // Contact_Sheet: made in stage 2
    bool failed = false;  // the log holds the fatal message
    std::string failure;  // ... and this is it (for the run log)
    // The parse stopped on a file that an earlier frame of this run writes
    // (a scene showing the previous frames' images, as the example
    // advanced/desk does): stage 3 parses and renders it again once every
    // earlier frame is written, as povray's one-frame-after-another order.
    bool deferred = false;
    double parseSeconds = 0, prepareSeconds = 0, renderSeconds = 0, writeSeconds = 0,
           commitSeconds = 0;
};

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

double cpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

// The frame scheduler (DESIGN.md, "Data flow"): a oneTBB pipeline with a
// bounded number of frames in flight.
//   1. parse: serial, in frame order (a frame may #read what the one before
//      #wrote); also the Continue_Trace check and Pre_Frame_Command.
//   2. prepare + render: parallel across frames; the tiles of each frame
//      are spread over the same threads, so no core idles at a frame's tail.
//   3. write + journal + log + Post_Frame_Command: serial, in frame order,
//      so the journal, the console and every outcome (a failing frame, a
//      hook's *_Return action, Ctrl-C) are what a frame-after-frame run
//      gives: frames before the one that ends the run are written, later
//      ones never are.
class Run {
  public:
    Run(const options::RenderOptions& o, const Sequence& seq)
        : o_(o),
          seq_(seq),
          streams_(o),
          progress_(seq.animated ? progressModeFor(o.verbose, streams_.console(TextStream::Render),
                                                   isatty(STDERR_FILENO) != 0)
                                 : ProgressMode::Silent,
                    seq.frames.size(),
                    [this](const std::string& line) { say(TextStream::Render, line); }) {
        streams_.setOverlay(&progress_);
    }
    ~Run() {
        setEmergencyStop(nullptr);
        streams_.setOverlay(nullptr);
    }
    Run(const Run&) = delete;
    Run& operator=(const Run&) = delete;

    int execute() {
        const int code = executeRun();
        logEvent(LogLevel::Info, "run_end",
                 {{"outcome", code == 0   ? "finished"
                              : code == 2 ? "interrupted"
                                          : "failed"},
                  {"exit_code", code},
                  {"frames_finished", finished_.load()},
                  {"frames_kept", kept_.size()},
                  {"wall_seconds", wallSeconds_},
                  {"cpu_seconds", cpuSecondsUsed_}});
        if (runLog_)
            if (const std::string error = runLog_->close(); !error.empty())
                say(TextStream::Warning,
                    fmt::format("frameray: warning: the run log is incomplete: {}\n", error));
        return code;
    }

  private:
    int executeRun() {
        // povray says it in every frame's parse (a beta feature's notice).
        if (o_.realTimeRaytracing)
            say(TextStream::Warning,
                "frameray: warning: Real_Time_Raytracing: every frame renders once and no image "
                "is written (as povray 3.7 does without a display)\n");
        if (toFiles_ && !seq_.frames.empty()) {
            std::error_code ec;
            // Every frame and the journal are in the same folder, created
            // only when Output_File_Name names it as a folder ("dir/");
            // main refuses a missing folder otherwise (checkOutputFolder).
            if (const fs::path folder = seq_.frames.front().output.parent_path();
                !folder.empty() && !o_.outputFile.empty() && o_.outputFile.back() == '/')
                fs::create_directories(folder, ec);
            removeStaleTemporaries(seq_);
            journal_ = std::make_unique<Journal>(seq_.journal, settingsHash(o_), o_.continueTrace,
                                                 shardJournals(seq_));
            written_ = journal_->written();
            openRunLog();
            if (o_.contactSheet && seq_.animated)
                sheet_ = std::make_unique<ContactSheet>(seq_, o_.previewFps);
            if (journal_->discardedStale()) {
                logEvent(LogLevel::Warn, "journal_stale", {{"journal", seq_.journal.string()}});
                say(TextStream::Warning,
                    fmt::format("frameray: the journal {} was written with other settings; "
                                "rendering every frame again\n",
                                seq_.journal.string()));
            }
        }
        setEmergencyStop([this] { emergencyStop(); });

        HookValues scene = values(nullptr);
        switch (hook(ShellHook::PreScene, scene)) {
            case HookAction::Continue:
                break;
            case HookAction::SkipFrame:
            case HookAction::SkipAll:
                return finish();
            case HookAction::Quit:
                return 0;
            case HookAction::UserAbort:
                return userAbort();
            case HookAction::Fatal:
                return fatal("Pre_Scene_Command failed", nullptr);
        }

        runPipeline();
        removeUnfinishedTemporaries();
        progress_.done();
        writeStatistics();
        saveSheet(true);
        if (o_.verbose && seq_.animated)
            say(TextStream::Statistic, summaryTable(figures(), records_, kept_.size()));

        switch (outcome_.kind) {
            case Outcome::Kind::None:
            case Outcome::Kind::Finish:
                mergeShardStatistics();
                return makeVideo() ? finish() : 1;
            case Outcome::Kind::Quit:
                return 0;
            case Outcome::Kind::UserAbort:
                current_ = outcome_.frame;
                return userAbort();
            case Outcome::Kind::Fatal:
                return fatal(outcome_.why, outcome_.frame);
        }
        return finish();
    }

    // The run log beside an animation's frames (anim/run_log.h); a log
    // that cannot be opened is a warning, never the end of the run.
    void openRunLog() {
        // +O- writes no file beside the frames, this one neither.
        if (!seq_.animated || o_.logLevel == LogLevel::Off || toStdout_) return;
        const fs::path folder = seq_.frames.front().output.parent_path();
        const fs::path path = (folder.empty() ? fs::path(".") : folder) / seq_.runLogName;
        try {
            runLog_ = std::make_unique<RunLog>(path, o_.logLevel, o_.logFormat,
                                               o_.verbose ? &progress_ : nullptr);
        } catch (const std::exception& e) {
            say(TextStream::Warning, fmt::format("frameray: warning: no run log: {}\n", e.what()));
            return;
        }
        logEvent(LogLevel::Info, "run_start",
                 {{"scene", seq_.sceneName},
                  {"frames", seq_.frames.size()},
                  {"frames_in_all_shards", seq_.framesInAllShards},
                  {"shard", seq_.shardIndex},
                  {"shard_count", seq_.shardCount},
                  {"continue_trace", o_.continueTrace ? 1 : 0},
                  {"pid", static_cast<long long>(getpid())}});
        for (const std::string& warning : o_.optionWarnings)
            logEvent(LogLevel::Warn, "option_warning", {{"message", warning}});
    }

    void logEvent(LogLevel level, std::string_view kind,
                  std::initializer_list<LogField> fields) const {
        if (runLog_) runLog_->event(level, kind, fields);
    }

    // The frame failed: its log gets the fatal message, the run log an event.
    static void failJob(Job& job, const std::string& message) {
        job.log->message(sdl::Stream::Fatal, message);
        job.failed = true;
        job.failure = message;
    }

    size_t framesInFlight() const {
        // Shell-outs between frames keep POV-Ray's strict order: frame N's
        // Post_Frame_Command before frame N+1's Pre_Frame_Command.
        if (!o_.commands[static_cast<int>(ShellHook::PreFrame)].command.empty() ||
            !o_.commands[static_cast<int>(ShellHook::PostFrame)].command.empty())
            return 1;
        if (o_.framesInFlight > 0) return static_cast<size_t>(o_.framesInFlight);
        return std::min<size_t>(threads_ + 1, kMaxDefaultFramesInFlight);
    }

    void runPipeline() {
        threads_ = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
        inFlight_ = framesInFlight();
        runStart_ = Clock::now();
        cpuStart_ = cpuSeconds();
        logEvent(LogLevel::Info, "pipeline",
                 {{"threads", threads_}, {"frames_in_flight", inFlight_}});
        // Frames in flight are bounded by memory too: the first frame
        // renders alone (its tiles still use every core) and its growth
        // of the process is the estimate for the others.
        const bool measureFirst = inFlight_ > 1 && seq_.frames.size() > 1;
        // Radiosity_Stable: the first frame seeds the others' caches, so it
        // renders before any other starts.
        const bool stableFirst = o_.radiosityStable && !measureFirst && inFlight_ > 1;
        if (stableFirst) pipelinePhase(1, 1);
        if (measureFirst) {
            const std::uint64_t before = residentBytes();
            pipelinePhase(1, 1);
            const std::uint64_t peak = peakResidentBytes();
            frameMemory_ = peak > before ? peak - before : 0;
            memoryBudget_ = availableBytes();
            inFlight_ = framesWithin(inFlight_, frameMemory_, memoryBudget_);
            logEvent(LogLevel::Info, "memory_limit",
                     {{"frame_memory_bytes", frameMemory_},
                      {"memory_budget_bytes", memoryBudget_},
                      {"frames_in_flight", inFlight_}});
        }
        if (!(measureFirst || stableFirst) ||
            (!decided_ && !inputDone_ && next_ < seq_.frames.size()))
            pipelinePhase(inFlight_, std::numeric_limits<size_t>::max());
        wallSeconds_ = secondsSince(runStart_);
        cpuSecondsUsed_ = cpuSeconds() - cpuStart_;
    }

    // One parallel_pipeline over the next frames: at most `tokens` in
    // flight, ending after `renders` rendered frames (or the sequence).
    void pipelinePhase(size_t tokens, size_t renders) {
        rendersLeft_ = renders;

        // Ctrl-C while every thread is inside a long render: the watcher
        // cancels the pipeline (tiles included) so the run stops at once.
        std::mutex doneMutex;
        std::condition_variable doneCv;
        bool done = false;
        std::thread watcher([&] {
            std::unique_lock lock(doneMutex);
            while (!done) {
                doneCv.wait_for(lock, std::chrono::milliseconds(50));
                if (!done && stopRequested())
                    decide({Outcome::Kind::UserAbort, "", current_.load()});
                progress_.tick();
            }
        });
        try {
            tbb::parallel_pipeline(
                tokens,
                tbb::make_filter<void, Job*>(tbb::filter_mode::serial_in_order,
                                             [this](tbb::flow_control& fc) -> Job* {
                                                 Job* job = nextJob();
                                                 if (!job) fc.stop();
                                                 return job;
                                             }) &
                    tbb::make_filter<Job*, Job*>(tbb::filter_mode::parallel,
                                                 [this](Job* job) {
                                                     renderJob(*job);
                                                     return job;
                                                 }) &
                    tbb::make_filter<Job*, void>(tbb::filter_mode::serial_in_order,
                                                 [this](Job* job) { finishJob(*job); }),
                context_);
        } catch (...) {
            {
                std::lock_guard lock(doneMutex);
                done = true;
            }
            doneCv.notify_all();
            watcher.join();
            throw;
        }
        {
            std::lock_guard lock(doneMutex);
            done = true;
        }
        doneCv.notify_all();
        watcher.join();
    }

    // The first outcome wins; later frames are dropped.
    void decide(Outcome outcome) {
        std::lock_guard lock(decideMutex_);
        if (decided_) return;
        outcome_ = std::move(outcome);
        decided_ = true;
        context_.cancel_group_execution();
    }

    Job& newJob(Job::Kind kind, size_t position) {
        std::lock_guard lock(jobsMutex_);
        auto job = std::make_unique<Job>();
        job->kind = kind;
        job->index = jobs_.size();
        job->position = position;
        if (position < seq_.frames.size()) {
            job->spec = seq_.frames[position];
            job->frame = &job->spec;
        }
        // Only the oldest frame in flight prints as it goes; the others
        // hold their messages until it is out.
        job->log = std::make_unique<FrameLog>(streams_, job->index == head_);
        if (job->index == head_ && kind == Job::Kind::Render) current_ = job->frame;
        jobs_.push_back(std::move(job));
        return *jobs_.back();
    }

    // A job that ends the run; `frame` (kept in the job) is the one whose
    // Pre_Frame_Command decided it, if any.
    Job* stopJob(Outcome outcome, const FrameSpec* frame = nullptr) {
        inputDone_ = true;
        Job& job = newJob(Job::Kind::Stop, seq_.frames.size());
        job.stop = std::move(outcome);
        if (frame) {
            job.spec = *frame;
            job.stop.frame = &job.spec;
        }
        return &job;
    }

    // Stage 1: the next frame to render, parsed; nullptr when there is none.
    Job* nextJob() {
        while (!inputDone_ && !decided_ && next_ < seq_.frames.size() && rendersLeft_ > 0) {
            if (stopRequested()) return stopJob({Outcome::Kind::UserAbort, "", nullptr});
            const size_t position = next_++;
            const FrameSpec frame = seq_.frames[position];
            if (o_.continueTrace && journal_) {
                bool kept = false;
                {
                    std::lock_guard lock(journalMutex_);
                    kept = journal_->verified(frame.number, clockText(frame.clock), frame.output,
                                              hashes_);
                }
                if (kept) return &newJob(Job::Kind::Kept, position);
            }
            switch (hook(ShellHook::PreFrame, values(&frame))) {
                case HookAction::Continue:
                    break;
                case HookAction::SkipFrame:
                    continue;
                case HookAction::SkipAll:
                    return stopJob({Outcome::Kind::Finish, "", nullptr});
                case HookAction::Quit:
                    return stopJob({Outcome::Kind::Quit, "", nullptr});
                case HookAction::UserAbort:
                    return stopJob({Outcome::Kind::UserAbort, "", nullptr});
                case HookAction::Fatal:
                    return stopJob({Outcome::Kind::Fatal, "Pre_Frame_Command failed", nullptr},
                                   &frame);
            }
            Job& job = newJob(Job::Kind::Render, position);
            --rendersLeft_;
            parseJob(job, true);
            // A frame that failed to parse ends the run: later frames
            // could depend on what it should have written.
            if (job.failed) inputDone_ = true;
            return &job;
        }
        return nullptr;
    }

    // Whether `message` names the output file of a frame before `position`.
    bool namesEarlierOutput(const std::string& message, size_t position) const {
        for (size_t i = 0; i < position; ++i) {
            const std::string quoted =
                fmt::format("'{}'", seq_.frames[i].output.filename().string());
            if (message.find(quoted) != std::string::npos) return true;
        }
        return false;
    }

    // Parses the job's frame into job.scene; on an error the log holds it
    // and job.failed is set, or job.deferred when `mayDefer` and the error
    // names an earlier frame's output file.
    void parseJob(Job& job, bool mayDefer) {
        const FrameSpec& frame = *job.frame;
        const auto start = Clock::now();
        try {
            job.interpreter =
                std::make_unique<sdl::Interpreter>(contextFor(o_, seq_, frame), cache_, *job.log);
            job.scene.emplace(job.interpreter->parseFile(o_.inputFile));
        } catch (const sdl::SdlError& e) {
            if (mayDefer && namesEarlierOutput(e.what(), job.position)) {
                job.deferred = true;
                job.interpreter.reset();
                job.parseSeconds = secondsSince(start);
                return;
            }
            failJob(job, e.what());
        } catch (const std::bad_alloc&) {
            failJob(job, fmt::format("error: frame {}: out of memory while parsing the scene",
                                     frame.number));
        } catch (const std::exception& e) {
            failJob(job, fmt::format("error: frame {}: {}", frame.number, e.what()));
        }
        if (!job.failed && journal_) noteInputs(job);
        job.parseSeconds = secondsSince(start);
        if (!job.failed)
            logEvent(LogLevel::Debug, "parse_done",
                     {{"frame", frame.number},
                      {"clock", frame.clock},
                      {"seconds", job.parseSeconds},
                      {"deferred", job.deferred ? 1 : 0}});
    }

    // Stage 1, right after the parse: the files the frame read, hashed now
    // (each once per run), and those it wrote; files written by this or an
    // earlier frame of the sequence are not inputs.
    void noteInputs(Job& job) {
        for (const fs::path& p : job.interpreter->filesWritten()) {
            job.written.push_back(journalName(p));
            written_.insert(job.written.back());
        }
        std::set<std::string> read;
        for (const fs::path& p : job.interpreter->filesRead()) read.insert(journalName(p));
        for (const std::string& p : read) {
            if (written_.count(p)) continue;
            // An input that cannot be hashed now never verifies later: 0
            // stands for it.
            job.inputs.emplace_back(p, hashes_.hash(p).value_or(0));
        }
    }

    render::FrameSettings frameSettings(const image::GammaEncoding& gamma) const {
        render::FrameSettings f;
        f.width = o_.width;
        f.height = o_.height;
        f.window = {seq_.window.x0, seq_.window.y0, seq_.window.x1, seq_.window.y1};
        f.blockSize = o_.renderBlockSize;
        f.quality = o_.quality;
        // Only PNG and TGA carry povray's alpha; other types ignore +UA.
        f.alpha = o_.outputAlpha &&
                  (seq_.fileType == image::FileType::PNG || seq_.fileType == image::FileType::TGA ||
                   seq_.fileType == image::FileType::TGA_RLE);
        if (o_.antialias) {
            render::AntialiasSettings& aa = f.antialias;
            aa.method = o_.samplingMethod;
            // povray clips these (threshold and jitter to [0,1]).
            aa.threshold = std::clamp(o_.antialiasThreshold, 0.0, 1.0);
            aa.depth = o_.antialiasDepth;
            aa.jitter = o_.jitter ? std::clamp(o_.jitterAmount, 0.0, 1.0) : 0.0;
            aa.gamma = o_.antialiasGamma;
            aa.toLinear = [gamma](double v) { return gamma.toLinear(v); };
        }
        return f;
    }

    // What a frame's radiosity starts from and keeps: the cache file's
    // samples (Radiosity_From_File, read once); under Radiosity_Stable the
    // first frame rendered (alone: runPipeline's first phase) also keeps
    // its whole cache, and every later frame starts from it. Returns
    // whether this frame seeds the later ones.
    bool radiosityCarry(render::FrameSettings& settings) {
        if (o_.radiosityFromFile) {
            std::call_once(radiosityFileRead_, [this] {
                radiosityFile_ = std::make_shared<const std::vector<render::RadiositySample>>(
                    render::readRadiosityFile(o_.radiosityFile));
            });
            settings.radiosityStart = radiosityFile_;
        }
        const bool seeds = o_.radiosityStable && !radiosityStableStarted_.exchange(true);
        if (o_.radiosityStable && !seeds && radiosityStable_)
            settings.radiosityStart = radiosityStable_;
        settings.keepRadiosity = seeds || o_.radiosityToFile;
        return seeds;
    }
    void keepRadiosity(Job& job, render::FrameImage& image, bool seeds) {
        if (seeds)
            radiosityStable_ = std::make_shared<const std::vector<render::RadiositySample>>(
                o_.radiosityToFile ? image.radiosityCache : std::move(image.radiosityCache));
        if (o_.radiosityToFile) job.radiosityCache = std::move(image.radiosityCache);
    }

    // The frame's file: encoded into memory (+O-) or flushed under a
    // temporary name; stage 3 writes or renames it.
    void encodeJob(Job& job, const image::EncodedImage& file) const {
        const auto start = Clock::now();
        if (toStdout_) {
            job.encoded = image::encodeFile(seq_.fileType, file, "standard output");
        } else {
            const fs::path temporary =
                image::writeTemporary(job.frame->output, seq_.fileType, file);
            job.temporary = temporary;
            const auto hash = hashFile(temporary, &job.fileSize);
            if (!hash)
                throw std::runtime_error(
                    fmt::format("cannot read back '{}' for the journal", temporary.string()));
            job.fileHash = *hash;
        }
        job.writeSeconds = secondsSince(start);
    }

    // Output_AOVs' layers (render/aov_pass.h) and the EXR compression:
    // nothing is traced for them unless asked.
    void addLayers(image::EncodedImage& file, const render::World& world,
                   const render::FrameSettings& settings) const {
        if (seq_.fileType != image::FileType::EXR) return;
        file.compression = o_.exrCompression;
        if (!aovs_.any()) return;
        render::AovImage layers =
            render::renderAovs(world, aovs_, settings.width, settings.height, settings.window);
        file.extraNames = std::move(layers.names);
        file.extraValues = std::move(layers.values);
    }

    // Stage 2, in parallel: build the world, render, encode.
    void renderJob(Job& job) {
        if (job.kind != Job::Kind::Render || job.failed || job.deferred || decided_ ||
            stopRequested())
            return;
        progress_.started(job.frame->number);
        try {
            auto start = Clock::now();
            const render::World world(*job.scene);
            job.prepareSeconds = secondsSince(start);
            if (world.photons()) job.stats.photons = world.photons()->stats();
            start = Clock::now();
            const auto gamma = image::GammaEncoding::forScene(
                job.scene->globals.assumedGammaSet, job.scene->globals.assumedGamma,
                job.scene->renderVersion(), o_.fileGamma);
            render::FrameSettings settings = frameSettings(gamma);
            if (settings.alpha) refuseAlphaWith(*job.scene);
            const bool seeds = radiosityCarry(settings);
            render::FrameImage image = render::renderFrame(world, settings, job.stats);
            keepRadiosity(job, image, seeds);
            job.shapeTests = world.shapeTests();
            job.renderSeconds = secondsSince(start);
            // Encoding, compression and the flush to disk happen here, in
            // parallel; stage 3 only renames and journals.
            if ((toStdout_ || toFiles_) && !decided_) {
                start = Clock::now();
                image::EncodedImage file = fileImage(image, gamma);
                addLayers(file, world, settings);  // a render pass, timed with the render
                job.renderSeconds += secondsSince(start);
                if (sheet_)
                    job.thumbnail = shrinkToFit(rgb8Of(file), kThumbnailWidth, kThumbnailHeight);
                encodeJob(job, file);
            }
            logEvent(LogLevel::Debug, "render_done",
                     {{"frame", job.frame->number},
                      {"clock", job.frame->clock},
                      {"prepare_seconds", job.prepareSeconds},
                      {"render_seconds", job.renderSeconds},
                      {"encode_seconds", job.writeSeconds},
                      {"camera_rays", job.stats.rays.camera},
                      {"shadow_rays", job.stats.rays.shadow}});
        } catch (const sdl::SdlError& e) {
            failJob(job, e.what());
        } catch (const std::bad_alloc&) {
            failJob(job, fmt::format("error: frame {}: out of memory while building or "
                                     "rendering the frame",
                                     job.frame->number));
        } catch (const std::exception& e) {
            failJob(job, fmt::format("error: frame {}: {}", job.frame->number, e.what()));
        }
        job.scene.reset();
        job.interpreter.reset();
    }

    // Stage 3, serial in frame order: write, journal, messages, hooks.
    void finishJob(Job& job) {
        if (!decided_) finishInOrder(job);
        // The next frame in line prints from now on.
        std::lock_guard lock(jobsMutex_);
        head_ = job.index + 1;
        if (!job.temporary.empty()) {  // not committed: the run ended before this frame
            std::error_code ec;
            fs::remove(job.temporary, ec);
            job.temporary.clear();
        }
        job.log.reset();
        if (head_ < jobs_.size()) {
            Job& next = *jobs_[head_];
            // After a decided stop, later frames stay silent (povray stops
            // at the frame that failed).
            if (next.log && !decided_) next.log->goLive();
            current_ = next.kind == Job::Kind::Render ? next.frame : nullptr;
        } else {
            current_ = nullptr;
        }
    }

    void finishInOrder(Job& job) {
        if (stopRequested())
            return decide({Outcome::Kind::UserAbort, "",
                           job.kind == Job::Kind::Render ? job.frame : nullptr});
        if (job.kind == Job::Kind::Stop) return decide(job.stop);
        const FrameSpec& frame = *job.frame;
        const size_t index = job.position + 1;
        if (job.deferred) {
            // Every earlier frame is written now: parse again, render here.
            job.deferred = false;
            job.log = std::make_unique<FrameLog>(streams_, true);
            const double firstParse = job.parseSeconds;
            parseJob(job, false);
            job.parseSeconds += firstParse;
            renderJob(job);
        }
        if (job.kind == Job::Kind::Kept) {
            ++finished_;
            kept_.push_back({frame.number, frame.clock, frame.output.filename().string()});
            progress_.finished(frame.number, true);
            if (sheet_) sheet_->kept(frame);
            saveSheet(false);
            logEvent(LogLevel::Info, "kept",
                     {{"frame", frame.number},
                      {"clock", frame.clock},
                      {"file", frame.output.filename().string()}});
            if (o_.verbose)
                say(TextStream::Render,
                    fmt::format("frame {} ({} of {}): {} is finished already (Continue_Trace)\n",
                                frame.number, index, seq_.frames.size(), frame.output.string()));
            return;
        }
        FrameLog& log = *job.log;
        if (!job.failed && toStdout_) {
            const auto start = Clock::now();
            if (std::fwrite(job.encoded.data(), 1, job.encoded.size(), stdout) !=
                    job.encoded.size() ||
                std::fflush(stdout) != 0) {
                failJob(job, fmt::format("error: frame {}: cannot write the image to standard "
                                         "output: {}",
                                         frame.number, std::strerror(errno)));
            }
            job.encoded = {};
            job.commitSeconds = secondsSince(start);
            job.writeSeconds += job.commitSeconds;
        } else if (!job.failed && toFiles_) {
            const auto start = Clock::now();
            try {
                image::commitTemporary(job.temporary, frame.output);
                job.temporary.clear();
                if (journal_) {
                    std::lock_guard lock(journalMutex_);
                    journal_->record(frame.number, clockText(frame.clock), frame.output,
                                     job.fileSize, job.fileHash, job.inputs, job.written);
                }
            } catch (const std::exception& e) {
                failJob(job, fmt::format("error: frame {}: {}", frame.number, e.what()));
            }
            job.commitSeconds = secondsSince(start);
            job.writeSeconds += job.commitSeconds;
        }
        if (!job.failed && o_.radiosityToFile) {
            try {
                render::writeRadiosityFile(o_.radiosityFile, job.radiosityCache);
            } catch (const std::exception& e) {
                failJob(job, fmt::format("error: frame {}: {}", frame.number, e.what()));
            }
            job.radiosityCache = {};
        }
        if (job.failed) {
            logEvent(LogLevel::Error, "failed",
                     {{"frame", frame.number}, {"clock", frame.clock}, {"reason", job.failure}});
            if (toFiles_) saveLog(log, frame);
            if (sheet_) sheet_->failed(frame, job.failure);
            saveSheet(false);
            return decide({Outcome::Kind::Fatal, "", &frame});
        }
        ++finished_;
        records_.push_back({frame.number, frame.clock, frame.output.filename().string(),
                            job.stats.rays, std::move(job.shapeTests), job.parseSeconds,
                            job.prepareSeconds, job.renderSeconds, job.writeSeconds,
                            job.commitSeconds, job.stats.photons});
        const double seconds =
            job.parseSeconds + job.prepareSeconds + job.renderSeconds + job.writeSeconds;
        if (sheet_) {
            sheet_->rendered(frame, seconds, totalRays(job.stats.rays), job.thumbnail);
            job.thumbnail = {};
            saveSheet(false);
        }
        const std::string where = toFiles_    ? frame.output.string()
                                  : toStdout_ ? std::string("(standard output)")
                                              : std::string("(no file)");
        logEvent(LogLevel::Info, "written",
                 {{"frame", frame.number},
                  {"clock", frame.clock},
                  {"file", toFiles_ ? frame.output.filename().string() : std::string()},
                  {"bytes", job.fileSize},
                  {"parse_seconds", job.parseSeconds},
                  {"prepare_seconds", job.prepareSeconds},
                  {"render_seconds", job.renderSeconds},
                  {"write_seconds", job.writeSeconds},
                  {"camera_rays", job.stats.rays.camera},
                  {"shadow_rays", job.stats.rays.shadow}});
        if (o_.verbose) {
            log.message(TextStream::Render, fmt::format("frame {} ({} of {}): {}\n", frame.number,
                                                        index, seq_.frames.size(), where));
            log.message(
                TextStream::Statistic,
                fmt::format("frame {}: {:.2f} s, {} camera rays, {} shadow rays\n", frame.number,
                            seconds, job.stats.rays.camera, job.stats.rays.shadow));
            if (const auto& ph = job.stats.photons)
                log.message(TextStream::Statistic,
                            fmt::format("frame {}: photons: {}, {} stored on surfaces, {} in "
                                        "media, gather radius {:.4g} (media {:.4g})\n",
                                        frame.number,
                                        ph->loaded ? std::string("loaded from file")
                                                   : fmt::format("{} shot", ph->shot),
                                        ph->stored, ph->mediaStored, ph->gatherRadius,
                                        ph->mediaGatherRadius));
            if (job.stats.rays.radiosity)
                log.message(
                    TextStream::Statistic,
                    fmt::format("frame {}: radiosity: {} rays, {} samples gathered ({} for "
                                "radiosity rays), {} lookups answered from the cache\n",
                                frame.number, job.stats.rays.radiosity, job.stats.radiosity.samples,
                                job.stats.radiosity.deeper, job.stats.radiosity.reused));
        }
        // The image is complete and journalled already: a log that cannot
        // be written ends the run but keeps the frame.
        if (toFiles_ && !saveLog(log, frame)) return decide({Outcome::Kind::Fatal, "", &frame});
        progress_.finished(frame.number, false, seconds);
        switch (hook(ShellHook::PostFrame, values(&frame))) {
            case HookAction::Continue:
            case HookAction::SkipFrame:
                break;
            case HookAction::SkipAll:
                return decide({Outcome::Kind::Finish, "", nullptr});
            case HookAction::Quit:
                return decide({Outcome::Kind::Quit, "", nullptr});
            case HookAction::UserAbort:
                return decide({Outcome::Kind::UserAbort, "", nullptr});
            case HookAction::Fatal:
                return decide({Outcome::Kind::Fatal, "Post_Frame_Command failed", &frame});
        }
    }

    // Writes the frame's log; on failure says why (on the console: the log
    // itself is what failed) and returns false.
    bool saveLog(FrameLog& log, const FrameSpec& frame) const {
        try {
            log.save(frame.log);
            return true;
        } catch (const std::exception& e) {
            say(TextStream::Fatal, fmt::format("error: frame {}: {}\n", frame.number, e.what()));
            return false;
        }
    }

    RunFigures figures() const {
        RunFigures f;
        f.scene = seq_.sceneName;
        f.framesPlanned = seq_.frames.size();
        f.framesFinished = finished_.load();
        f.workThreads = threads_;
        f.framesInFlight = inFlight_;
        f.wallSeconds = wallSeconds_;
        f.cpuSeconds = cpuSecondsUsed_;
        f.frameMemoryEstimate = frameMemory_;
        f.memoryBudget = memoryBudget_;
        f.shardIndex = seq_.shardIndex;
        f.shardCount = seq_.shardCount;
        return f;
    }

    // sequence.json (a shard's own sequence.shard-I-of-N.json) beside the
    // frames of an animation: per-frame statistics, their sums, and how
    // busy the cores were.
    void writeStatistics() const {
        if (!toFiles_ || !seq_.animated || seq_.frames.empty()) return;
        const fs::path dir = seq_.frames.front().output.parent_path();
        const fs::path path = (dir.empty() ? fs::path(".") : dir) / seq_.statisticsName;
        const std::string text = sequenceJson(figures(), records_, kept_);
        try {
            util::replaceFileDurably(path, text);
        } catch (const std::exception& e) {
            logEvent(LogLevel::Warn, "write_failed",
                     {{"file", path.string()}, {"reason", std::string(e.what())}});
            say(TextStream::Warning, fmt::format("frameray: warning: {}\n", e.what()));
        }
    }

    // A shard that has finished its frames merges every shard's statistics
    // into sequence.json when all of them have finished theirs: the last
    // shard to finish makes the sequence's one view (as `frameray
    // --merge-stats DIR` does). Until then it says what it waits for.
    void mergeShardStatistics() const {
        if (!toFiles_ || !seq_.animated || seq_.shardCount <= 1 || seq_.frames.empty() ||
            finished_.load() < seq_.frames.size())
            return;
        const fs::path dir = seq_.frames.front().output.parent_path();
        try {
            const MergedStatistics merged = mergeShardStatisticsIn(dir.empty() ? "." : dir);
            logEvent(LogLevel::Info, "statistics_merged",
                     {{"file", merged.file.string()}, {"shards", merged.shards}});
            if (o_.verbose)
                say(TextStream::Render, fmt::format("statistics of the {} shards merged into {}\n",
                                                    merged.shards, merged.file.string()));
        } catch (const std::exception& e) {
            logEvent(LogLevel::Info, "statistics_waiting", {{"reason", std::string(e.what())}});
        }
    }

    // Preview_Video, once every frame of the whole sequence (every shard's)
    // is on disk: the run that completes it makes the video (a shard that
    // finishes before the others, or a run stopped early, makes none; a
    // later +C run does). A video that cannot be made fails the run; the
    // frames stay as they are.
    bool makeVideo() {
        if (o_.previewVideo.empty() || !toFiles_ || !seq_.animated) return true;
        options::RenderOptions whole = o_;
        whole.shardIndex = 0;
        whole.shardCount = 1;
        const Sequence all = planSequence(whole);
        std::vector<fs::path> frames;
        size_t present = 0;
        for (const FrameSpec& f : all.frames) {
            std::error_code ec;
            present += fs::is_regular_file(f.output, ec);
            frames.push_back(f.output);
        }
        if (present < frames.size()) {
            logEvent(LogLevel::Info, "video_waiting",
                     {{"frames_present", present}, {"frames", frames.size()}});
            if (o_.verbose)
                say(TextStream::Render,
                    fmt::format("preview video: {} of {} frames exist; the run that completes the "
                                "sequence makes it\n",
                                present, frames.size()));
            return true;
        }
        const fs::path folder = all.frames.front().output.parent_path();
        const fs::path video =
            (folder.empty() ? fs::path(".") : folder) / (seq_.sceneName + "." + o_.previewVideo);
        try {
            makePreviewVideo(frames, video, o_.previewVideo, o_.previewFps);
        } catch (const std::exception& e) {
            logEvent(LogLevel::Error, "video_failed", {{"reason", std::string(e.what())}});
            say(TextStream::Fatal, fmt::format("frameray: error: preview video: {}\n", e.what()));
            return false;
        }
        logEvent(LogLevel::Info, "video", {{"file", video.string()}, {"frames", frames.size()}});
        if (o_.verbose)
            say(TextStream::Render, fmt::format("preview video: {} ({} frames at {} per second)\n",
                                                video.string(), frames.size(), o_.previewFps));
        return true;
    }

    // The contact sheet, when asked for: a page that cannot be written is
    // a warning (the frames are what matters), said once.
    void saveSheet(bool final) {
        if (!sheet_) return;
        try {
            sheet_->save(final);
        } catch (const std::exception& e) {
            logEvent(LogLevel::Warn, "write_failed",
                     {{"file", sheet_->pagePath().string()}, {"reason", std::string(e.what())}});
            say(TextStream::Warning,
                fmt::format("frameray: warning: contact sheet: {}\n", e.what()));
            sheet_.reset();
        }
    }

    // Frames cancelled after their image was staged (the pipeline drops
    // them without stage 3) leave no temporary file behind.
    void removeUnfinishedTemporaries() {
        std::lock_guard lock(jobsMutex_);
        for (auto& job : jobs_)
            if (!job->temporary.empty()) {
                std::error_code ec;
                fs::remove(job->temporary, ec);
                job->temporary.clear();
            }
    }

    int finish() {
        switch (hook(ShellHook::PostScene, values(nullptr))) {
            case HookAction::UserAbort:
                return userAbort();
            case HookAction::Fatal:
                return fatal("Post_Scene_Command failed", nullptr);
            default:
                return 0;
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

    void say(TextStream stream, const std::string& text) const { streams_.write(stream, text); }

    // A *_Command hook, run and logged (nothing when the option is empty).
    HookAction hook(ShellHook which, const HookValues& v) {
        const options::ShellCommand& command = o_.commands[static_cast<int>(which)];
        if (command.command.empty()) return HookAction::Continue;
        const auto start = Clock::now();
        int exitCode = 0;
        const HookAction action = runHook(command, v, &exitCode);
        logEvent(exitCode == 0 ? LogLevel::Info : LogLevel::Warn, "hook",
                 {{"hook", options::kShellHookNames[static_cast<int>(which)]},
                  {"frame", v.frame},
                  {"clock", v.clock},
                  {"exit_code", exitCode},
                  {"action", kHookActionNames[static_cast<int>(action)]},
                  {"seconds", secondsSince(start)}});
        return action;
    }

    int fatal(const std::string& why, const FrameSpec* frame) {
        if (!why.empty()) {
            logEvent(LogLevel::Error, "fatal",
                     {{"reason", why}, {"frame", frame ? frame->number : 0}});
            say(TextStream::Fatal, fmt::format("frameray: error: {}\n", why));
        }
        hook(ShellHook::FatalError, values(frame));
        return 1;
    }

    std::string stopMessage() const {
        return fmt::format(
            "frameray: interrupted; {} of {} frames are finished{}\n", finished_.load(),
            seq_.frames.size(),
            journal_ ? " - run again with +C (Continue_Trace=on) to render the rest" : "");
    }

    int userAbort() {
        acknowledgeStop();
        logEvent(LogLevel::Warn, "interrupted", {{"frames_finished", finished_.load()}});
        say(TextStream::Fatal, stopMessage());
        hook(ShellHook::UserAbort, values(current_));
        return 2;
    }

    // Runs on the watcher thread when the run missed the grace time. Only
    // the frame at the head of the pipeline can be writing its image.
    void emergencyStop() {
        // Any frame in flight may have staged its image.
        {
            std::unique_lock lock(jobsMutex_, std::try_to_lock);
            if (lock.owns_lock())
                for (const auto& job : jobs_)
                    if (job->frame) {
                        std::error_code ec;
                        fs::remove(image::temporaryPathFor(job->frame->output), ec);
                    }
        }
        std::fputs(stopMessage().c_str(), stderr);
        hook(ShellHook::UserAbort, values(current_));
    }

    static constexpr size_t kMaxDefaultFramesInFlight = 16;

    const options::RenderOptions& o_;
    // Output_File_Name=- (+O-): the images go to standard output, one
    // after another in frame order (povray writes them there too); no
    // files, journal, frame logs or sequence.json then.
    const bool toStdout_ = o_.writesImages() && o_.outputFile == "-";
    const bool toFiles_ = o_.writesImages() && !toStdout_;
    const render::AovRequest aovs_ = aovRequest(o_);

    // povray writes grey PNG files with 16 bits whatever the depth asked
    // (measured: Grayscale_Output with +FN8 gives a 16-bit grey PNG).
    int fileBitDepth() const {
        return o_.grayscaleOutput && seq_.fileType == image::FileType::PNG ? 16 : o_.bitDepth;
    }

    // A rendered frame as the file's values: gamma, window, alpha, grey
    // (Grayscale_Output) and the dithering asked for (Dither).
    image::EncodedImage fileImage(const render::FrameImage& frame,
                                  const image::GammaEncoding& gamma) const {
        image::EncodedImage out =
            image::encodeFrame(frame.width, frame.height, frame.rgb, frame.alpha, gamma,
                               fileBitDepth(), seq_.window, o_.grayscaleOutput);
        out.gamma = o_.fileGamma;  // stated in PNG files (gAMA, sRGB)
        if (o_.dither) {
            static constexpr std::pair<std::string_view, image::Dither> kMethods[] = {
                {"FS", image::Dither::FloydSteinberg},
                {"B2", image::Dither::Bayer2},
                {"B3", image::Dither::Bayer3},
                {"B4", image::Dither::Bayer4}};
            for (const auto& [name, method] : kMethods)
                if (o_.ditherMethod == name) out.dither = method;
        }
        return out;
    }
    const Sequence& seq_;
    mutable RunStreams streams_;
    Progress progress_;
    sdl::TokenCache cache_;  // shared by the frames: files are lexed once
    std::unique_ptr<Journal> journal_;
    std::unique_ptr<RunLog> runLog_;       // null: no run log
    std::unique_ptr<ContactSheet> sheet_;  // null: no Contact_Sheet
    FileHashes hashes_;                    // input files' hashes, read once per run
    // Files the sequence's frames wrote (stage 1 adds each frame's as it
    // is parsed): state passed between frames, not inputs.
    std::set<std::string> written_;
    std::mutex journalMutex_;
    std::atomic<const FrameSpec*> current_{nullptr};  // the oldest frame in flight
    std::atomic<size_t> finished_{0};

    // Pipeline state. Stage 1 alone touches next_ and inputDone_; jobs_
    // and head_ are shared with stage 3 under jobsMutex_.
    tbb::task_group_context context_;
    size_t next_ = 0;
    bool inputDone_ = false;
    std::mutex jobsMutex_;
    std::deque<std::unique_ptr<Job>> jobs_;
    size_t head_ = 0;
    std::mutex decideMutex_;
    std::once_flag radiosityFileRead_;
    std::shared_ptr<const std::vector<render::RadiositySample>> radiosityFile_;
    // Radiosity_Stable: whether the seeding frame has started, and its cache.
    std::atomic<bool> radiosityStableStarted_{false};
    std::shared_ptr<const std::vector<render::RadiositySample>> radiosityStable_;
    std::atomic<bool> decided_{false};
    Outcome outcome_;

    // Statistics (stage 3 appends; read after the pipeline).
    std::vector<FrameRecord> records_;
    std::vector<KeptFrame> kept_;
    std::uint64_t frameMemory_ = 0, memoryBudget_ = 0;
    size_t rendersLeft_ = 0;  // stage 1 of the current pipeline phase
    size_t threads_ = 1;
    size_t inFlight_ = 1;
    Clock::time_point runStart_;
    double cpuStart_ = 0, wallSeconds_ = 0, cpuSecondsUsed_ = 0;
};

}  // namespace

int runSequence(const options::RenderOptions& o, const Sequence& seq) {
    // The image module (OpenImageIO) loads on another core while the first
    // frame parses (image/codecs.h).
    // PNG frames are written without it (image/png_writer.h).
    if (o.writesImages() && !seq.frames.empty() && seq.fileType != image::FileType::PNG)
        image::preloadCodecs();
    if (seq.frames.empty()) {
        // More shards than frames: nothing is this shard's.
        if (o.verbose)
            std::fprintf(stderr,
                         "frameray: shard %d of %d has no frames of the %zu in the sequence\n",
                         seq.shardIndex, seq.shardCount, seq.framesInAllShards);
        return 0;
    }
    // A preview video that could not be made is known before any frame.
    if (!o.previewVideo.empty() && o.writesImages() && o.outputFile != "-" && seq.animated) try {
            checkVideoEncoder(o.previewVideo);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "frameray: error: %s\n", e.what());
            return 2;
        }
    // Shell-outs are refused before anything runs unless allowed.
    if (const std::string refusal = shellCommandRefusal(o); !refusal.empty()) {
        std::fprintf(stderr, "frameray: error: %s\n", refusal.c_str());
        return 2;
    }
    try {
        Run run(o, seq);
        return run.execute();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "frameray: error: %s\n", e.what());
        return 1;
    }
}

}  // namespace frameray::anim

// frameray's own run log: what the frame loop does with a sequence (frames
// parsed, rendered, written, kept by +C, failed; memory and shard
// decisions; how the run ended) as events with a level, written through
// spdlog to NAME.frameray.log beside an animation's frames. The scene's
// own text (#debug and POV-Ray's six streams) and the per-frame logs are
// not part of it: povray's semantics rule those.
//
// Lines are text ("2026-11-27 23:59:01.123 info  written frame=3 ...") or,
// with Log_Format=json, one JSON object per line that a farm monitor can
// follow while the sequence renders (`tail -f | jq`):
//     {"time":"...","level":"info","event":"written","frame":3,"clock":0.25,...}
// The file is appended to, so a +C run adds its `kept` events after the
// first run's. Logging is asynchronous (a queue drained by one spdlog
// thread of this run's own): the frame pipeline never waits for the disk.
// Every write is checked (util::DurableAppendFile); a failure is reported
// once at the end of the run and never stops a frame.
#pragma once

#include <concepts>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>
#include <variant>

#include "options/render_options.h"

namespace spdlog {
class logger;
namespace details {
class thread_pool;
}
}  // namespace spdlog

namespace frameray::anim {

class ConsoleOverlay;

// One name = value pair of an event.
struct LogField {
    std::string_view key;
    std::variant<long long, double, std::string> value;

    template <std::integral I>
    LogField(std::string_view k, I v) : key(k), value(static_cast<long long>(v)) {}
    LogField(std::string_view k, double v) : key(k), value(v) {}
    LogField(std::string_view k, std::string v) : key(k), value(std::move(v)) {}
    LogField(std::string_view k, const char* v) : key(k), value(std::string(v)) {}
};

// The part of a line after the time and level: `kind` and the fields, as
// JSON members (`"event":"written","frame":3`) or as text
// (`written frame=3 file="a.png"`). Exposed for tests.
std::string formatEvent(options::LogFormat format, std::string_view kind,
                        std::initializer_list<LogField> fields);

class RunLog {
  public:
    // No log at all (Log_Level=off, stills, no output files).
    RunLog() = default;
    // Appends to `path` (created if missing). Events below `level` are
    // dropped. When `consoleOverlay` is set, debug events are also printed
    // on stderr around it (the other levels have their console messages
    // already). Throws std::runtime_error when the file cannot be opened.
    RunLog(const std::filesystem::path& path, options::LogLevel level, options::LogFormat format,
           ConsoleOverlay* consoleOverlay);
    ~RunLog();
    RunLog(const RunLog&) = delete;
    RunLog& operator=(const RunLog&) = delete;

    bool enabled(options::LogLevel level) const;
    void event(options::LogLevel level, std::string_view kind,
               std::initializer_list<LogField> fields = {});

    // Drains the queue and closes the file; returns the first write error
    // ("" when every line was written). Later events are dropped.
    std::string close();

  private:
    class FileSink;
    options::LogLevel level_ = options::LogLevel::Off;
    options::LogFormat format_ = options::LogFormat::Text;
    std::shared_ptr<spdlog::details::thread_pool> pool_;
    std::shared_ptr<FileSink> file_;
    std::shared_ptr<spdlog::logger> logger_;
};

}  // namespace frameray::anim

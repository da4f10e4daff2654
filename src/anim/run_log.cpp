#include "anim/run_log.h"

#include <fmt/format.h>
#include <spdlog/async_logger.h>
#include <spdlog/details/thread_pool.h>
#include <spdlog/sinks/base_sink.h>

#include <cmath>
#include <cstdio>
#include <mutex>

#include "anim/frame_log.h"
#include "anim/statistics.h"
#include "util/durable_file.h"

namespace frameray::anim {

namespace {

using options::LogFormat;
using options::LogLevel;

spdlog::level::level_enum toSpdlog(LogLevel level) {
    switch (level) {
        case LogLevel::Debug:
            return spdlog::level::debug;
        case LogLevel::Info:
            return spdlog::level::info;
        case LogLevel::Warn:
            return spdlog::level::warn;
        case LogLevel::Error:
            return spdlog::level::err;
        case LogLevel::Off:
            break;
    }
    return spdlog::level::off;
}

// A JSON number; non-finite values (which JSON has no spelling for) are null.
std::string jsonNumber(double v) {
    return std::isfinite(v) ? fmt::format("{}", v) : std::string("null");
}

// spdlog's patterns: the time and level, then the event (formatEvent).
constexpr const char* kTextPattern = "%Y-%m-%d %H:%M:%S.%e %-7l %v";
constexpr const char* kJsonPattern = R"({"time":"%Y-%m-%dT%H:%M:%S.%f%z","level":"%l",%v})";

// Debug events on the console, kept out of the progress line.
class ConsoleSink final : public spdlog::sinks::base_sink<std::mutex> {
  public:
    explicit ConsoleSink(ConsoleOverlay* overlay) : overlay_(overlay) {}

  protected:
    void sink_it_(const spdlog::details::log_msg& msg) override {
        if (msg.level != spdlog::level::debug) return;
        spdlog::memory_buf_t line;
        formatter_->format(msg, line);
        overlay_->hide();
        std::fwrite(line.data(), 1, line.size(), stderr);
        overlay_->show();
    }
    void flush_() override { std::fflush(stderr); }

  private:
    ConsoleOverlay* overlay_;
};

}  // namespace

// The log file: every line on the device when its write returns; the first
// failure is kept (and later lines dropped) for close() to report.
class RunLog::FileSink final : public spdlog::sinks::base_sink<std::mutex> {
  public:
    explicit FileSink(const std::filesystem::path& path) : file_(path, false) {}

    std::string error() {
        std::lock_guard lock(mutex_);
        return error_;
    }

  protected:
    void sink_it_(const spdlog::details::log_msg& msg) override {
        if (!error_.empty()) return;
        spdlog::memory_buf_t line;
        formatter_->format(msg, line);
        try {
            file_.append(std::string_view(line.data(), line.size()));
        } catch (const std::exception& e) {
            error_ = e.what();
        }
    }
    void flush_() override {}

  private:
    util::DurableAppendFile file_;
    std::string error_;
};

std::string formatEvent(LogFormat format, std::string_view kind,
                        std::initializer_list<LogField> fields) {
    const bool json = format == LogFormat::Json;
    std::string out =
        json ? fmt::format("\"event\":{}", jsonString(std::string(kind))) : std::string(kind);
    for (const LogField& f : fields) {
        std::string value;
        if (const auto* i = std::get_if<long long>(&f.value))
            value = fmt::format("{}", *i);
        else if (const auto* d = std::get_if<double>(&f.value))
            value = jsonNumber(*d);
        else
            value = jsonString(std::get<std::string>(f.value));
        out += json ? fmt::format(",\"{}\":{}", f.key, value) : fmt::format(" {}={}", f.key, value);
    }
    return out;
}

RunLog::RunLog(const std::filesystem::path& path, LogLevel level, LogFormat format,
               ConsoleOverlay* consoleOverlay)
    : level_(level), format_(format) {
    if (level == LogLevel::Off) return;
    file_ = std::make_shared<FileSink>(path);
    file_->set_pattern(format == LogFormat::Json ? kJsonPattern : kTextPattern);
    std::vector<spdlog::sink_ptr> sinks{file_};
    if (consoleOverlay && level == LogLevel::Debug) {
        auto console = std::make_shared<ConsoleSink>(consoleOverlay);
        console->set_pattern("frameray: %v");
        sinks.push_back(console);
    }
    // This run's own queue and thread (spdlog's global registry and pool
    // stay unused: frames and runs share no mutable state). A full queue
    // makes the caller wait rather than lose an event.
    pool_ = std::make_shared<spdlog::details::thread_pool>(8192, 1);
    logger_ = std::make_shared<spdlog::async_logger>("frameray", sinks.begin(), sinks.end(), pool_,
                                                     spdlog::async_overflow_policy::block);
    logger_->set_level(toSpdlog(level));
}

RunLog::~RunLog() {
    close();
}

bool RunLog::enabled(LogLevel level) const {
    return logger_ && level != LogLevel::Off && level >= level_;
}

void RunLog::event(LogLevel level, std::string_view kind, std::initializer_list<LogField> fields) {
    if (!enabled(level)) return;
    logger_->log(toSpdlog(level), formatEvent(format_, kind, fields));
}

std::string RunLog::close() {
    if (!logger_) return {};
    // The pool's thread writes every queued line before it ends.
    logger_.reset();
    pool_.reset();
    std::string error = file_->error();
    file_.reset();
    return error;
}

}  // namespace frameray::anim

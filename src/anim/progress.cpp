#include "anim/progress.h"

#include <fmt/format.h>

#include <cmath>

namespace frameray::anim {

ProgressMode progressModeFor(bool verbose, bool renderConsole, bool consoleIsTerminal) {
    if (!verbose || !renderConsole) return ProgressMode::Silent;
    return consoleIsTerminal ? ProgressMode::Terminal : ProgressMode::Lines;
}

double estimateRemaining(size_t rendered, size_t kept, size_t total, double elapsed) {
    const size_t done = rendered + kept;
    if (done >= total) return 0;
    if (rendered == 0) return -1;
    return elapsed / static_cast<double>(rendered) * static_cast<double>(total - done);
}

std::string formatDuration(double seconds) {
    if (seconds < 0) return "?";
    if (seconds < 60) return fmt::format("{:.1f} s", seconds);
    const long s = std::lround(seconds);
    if (s < 3600) return fmt::format("{} min {:02} s", s / 60, s % 60);
    return fmt::format("{} h {:02} min", s / 3600, (s % 3600) / 60);
}

Progress::Progress(ProgressMode mode, size_t total,
                   std::function<void(const std::string&)> printLine)
    : mode_(mode), total_(total), printLine_(std::move(printLine)), start_(Clock::now()) {}

double Progress::elapsed() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
}

std::string Progress::terminalLine(size_t done, size_t total, const std::set<int>& current,
                                   double elapsed, double remaining, const Pace& pace) {
    const double percent =
        total ? 100.0 * static_cast<double>(done) / static_cast<double>(total) : 100.0;
    std::string rendering;
    size_t shown = 0;
    for (const int f : current) {
        if (++shown > 6) {
            rendering += " ...";
            break;
        }
        rendering += fmt::format(" {}", f);
    }
    std::string speed;
    if (pace.fps >= 0) speed += fmt::format(" | {:.2f} frames/s", pace.fps);
    if (pace.slowestSeconds >= 0)
        speed += fmt::format(" | slowest {} ({})", pace.slowestFrame,
                             formatDuration(pace.slowestSeconds));
    return fmt::format("frames {}/{} ({:.0f}%){} | rendering{} | elapsed {} | ETA {}", done, total,
                       percent, speed, rendering.empty() ? " -" : rendering,
                       formatDuration(elapsed), formatDuration(remaining));
}

void Progress::started(int frame) {
    if (mode_ != ProgressMode::Terminal) return;
    std::lock_guard lock(mutex_);
    current_.insert(frame);
    draw(false);
}

// Frames this run rendered per second of the run so far (kept frames cost
// nothing), and the slowest of them.
Progress::Pace Progress::pace(double elapsed) const {
    Pace p;
    if (rendered_ > 0 && elapsed > 0) p.fps = static_cast<double>(rendered_) / elapsed;
    p.slowestFrame = slowestFrame_;
    p.slowestSeconds = slowestSeconds_;
    return p;
}

void Progress::finished(int frame, bool kept, double seconds) {
    if (mode_ == ProgressMode::Silent) return;
    std::string line;
    {
        std::lock_guard lock(mutex_);
        current_.erase(frame);
        ++(kept ? kept_ : rendered_);
        if (!kept && seconds > slowestSeconds_) {
            slowestSeconds_ = seconds;
            slowestFrame_ = frame;
        }
        const double t = elapsed();
        if (mode_ == ProgressMode::Terminal) {
            draw(true);
            return;
        }
        // Times printed with two decimals and " s", the way the frame
        // statistics print theirs.
        const double remaining = estimateRemaining(rendered_, kept_, total_, t);
        const Pace p = pace(t);
        line = fmt::format(
            "progress: frame {}{} - {} of {} done, elapsed {:.2f} s, ETA {}{}{}\n", frame,
            kept ? " (kept)" : "", rendered_ + kept_, total_, t,
            remaining < 0 ? std::string("unknown") : fmt::format("{:.2f} s", remaining),
            p.fps < 0 ? std::string() : fmt::format(", {:.2f} frames/s", p.fps),
            p.slowestSeconds < 0
                ? std::string()
                : fmt::format(", slowest frame {} ({:.2f} s)", p.slowestFrame, p.slowestSeconds));
    }
    printLine_(line);
}

void Progress::tick() {
    if (mode_ != ProgressMode::Terminal) return;
    std::lock_guard lock(mutex_);
    draw(false);
}

void Progress::draw(bool force) {
    if (finished_) return;
    const auto now = Clock::now();
    if (!force && visible_ && now - lastDraw_ < std::chrono::milliseconds(100)) return;
    lastDraw_ = now;
    const double t = elapsed();
    const std::string line = terminalLine(rendered_ + kept_, total_, current_, t,
                                          estimateRemaining(rendered_, kept_, total_, t), pace(t));
    // Carriage return, the line, erase to its end.
    std::fprintf(stderr, "\r%s\033[K", line.c_str());
    std::fflush(stderr);
    visible_ = true;
}

void Progress::hide() {
    if (mode_ != ProgressMode::Terminal) return;
    std::lock_guard lock(mutex_);
    if (!visible_) return;
    std::fputs("\r\033[K", stderr);
    visible_ = false;
}

void Progress::show() {
    if (mode_ != ProgressMode::Terminal) return;
    std::lock_guard lock(mutex_);
    draw(true);
}

void Progress::done() {
    if (mode_ != ProgressMode::Terminal) return;
    std::lock_guard lock(mutex_);
    if (!finished_) {
        draw(true);
        std::fputs("\n", stderr);
        std::fflush(stderr);
    }
    finished_ = true;
    visible_ = false;
}

}  // namespace frameray::anim

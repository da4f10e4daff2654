// Progress of an animation on the console: on a terminal one line that
// keeps updating (frames done/total, frames rendered per second, the
// slowest frame so far, the frames rendering now, elapsed time, ETA);
// elsewhere a plain line per finished frame; nothing with -V.
#pragma once

#include <chrono>
#include <cstdio>
#include <functional>
#include <mutex>
#include <set>
#include <string>

#include "anim/frame_log.h"

namespace frameray::anim {

enum class ProgressMode { Silent, Lines, Terminal };

// Terminal when the console is a terminal, Lines when it is not, Silent
// when the run is not verbose or does not print render messages.
ProgressMode progressModeFor(bool verbose, bool renderConsole, bool consoleIsTerminal);

// Seconds still to go at the pace so far; negative when unknown (nothing
// rendered yet). `kept` frames (finished by an earlier run) took no time.
double estimateRemaining(size_t rendered, size_t kept, size_t total, double elapsed);

// "12.3 s", "4 min 05 s", "2 h 03 min".
std::string formatDuration(double seconds);

// Frames rendered per second and the slowest frame so far; fps < 0 or
// slowestSeconds < 0: not known yet (left out of the line).
struct ProgressPace {
    double fps = -1;
    int slowestFrame = 0;
    double slowestSeconds = -1;
};

class Progress final : public ConsoleOverlay {
  public:
    using Clock = std::chrono::steady_clock;
    // `printLine` prints a Lines-mode line (through the run's streams);
    // the terminal line is drawn straight on stderr.
    Progress(ProgressMode mode, size_t total, std::function<void(const std::string&)> printLine);

    ProgressMode mode() const { return mode_; }

    void started(int frame);
    // `seconds`: the frame's own time (parse to write), for the slowest.
    void finished(int frame, bool kept, double seconds = 0);
    // Redraws the terminal line (elapsed time moves); cheap, rate limited.
    void tick();
    // Around other console output, so it does not land inside the line.
    void hide() override;
    void show() override;
    // Ends the terminal line before the summary.
    void done();

    // The text of the terminal line (exposed for tests).
    using Pace = ProgressPace;
    static std::string terminalLine(size_t done, size_t total, const std::set<int>& current,
                                    double elapsed, double remaining, const Pace& pace = {});

  private:
    void draw(bool force);  // mutex held
    double elapsed() const;

    ProgressMode mode_;
    size_t total_;
    std::function<void(const std::string&)> printLine_;
    Clock::time_point start_;
    std::mutex mutex_;
    size_t rendered_ = 0, kept_ = 0;
    Pace pace(double elapsed) const;  // mutex held
    int slowestFrame_ = 0;
    double slowestSeconds_ = -1;
    std::set<int> current_;
    bool visible_ = false;
    bool finished_ = false;
    Clock::time_point lastDraw_{};
};

}  // namespace frameray::anim

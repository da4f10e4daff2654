// Stopping a run with Ctrl-C (SIGINT) or SIGTERM. A signal handler wakes
// a watcher thread: it raises a flag the frame loop checks between steps;
// when the loop does not reach such a point within the grace time (a frame
// still rendering), the watcher runs the loop's emergency action (remove
// the half-written temporary image, run User_Abort_Command) and ends the
// process. Finished frames are on disk and in the journal either way, so
// the run resumes with +C.
#pragma once

#include <chrono>
#include <functional>

namespace frameray::anim {

// Installs the SIGINT/SIGTERM handler and starts the watcher; call it
// first in main.
void installInterruptWatcher(std::chrono::milliseconds grace = std::chrono::milliseconds(1500));

// True once a stop was requested.
bool stopRequested();

// The loop took the stop request at a safe point and will finish on its
// own: the watcher stands down.
void acknowledgeStop();

// What the watcher does when the loop misses the grace time, before it
// ends the process with exit status 2. Replaces any earlier action.
void setEmergencyStop(std::function<void()> action);

}  // namespace frameray::anim
